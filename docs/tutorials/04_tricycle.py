# ---
# jupyter:
#   jupytext:
#     text_representation:
#       extension: .py
#       format_name: percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # 4. The tricycle
#
# Two rear wheels on one axle (track $w$) and a steered front wheel at $\ell$ ahead of the
# rear-axle midpoint. All three roll without slip only if their axle lines meet in one
# point, the instantaneous centre $C$, at $R_C = \ell/\tan\phi$ from the midpoint along the
# rear axle. A rear wheel at lateral offset $b$ then rolls at $v - b\dot\psi$; with
# $k = (w/2\ell)\tan\phi$:
#
# $$ v_L = v(1-k),\qquad v_R = v(1+k),\qquad \dot\psi = \frac{v\tan\phi}{\ell}. $$
#
# Hence the lecture's remark: if one rear wheel is driven, the other must be free to take
# its own speed (or the two coupled by a differential); otherwise a wheel slips. The MuJoCo
# tricycle drives its left rear wheel and leaves the right one free
# (`wmr_mujoco.robots.tricycle.analytic`).
#
# ![the tricycle in MuJoCo](../../renders/tricycle.gif)

# %%
import matplotlib.pyplot as plt
import mujoco
import numpy as np

import wmr_mujoco as wmr
from wmr_mujoco.robots.tricycle import analytic as tricycle
from wmr_mujoco.robots.tricycle.params import TricycleParams
from wmr_mujoco.tutorials.checks import check_tricycle_icr

p = TricycleParams()
R, ell, w = p.rear_wheel.radius, p.wheelbase, p.track
print(f"rear wheel radius R = {R} m, wheelbase ℓ = {ell} m, track w = {w} m")

# %% [markdown]
# ## A figure of eight through model and physics
# The inputs are the midpoint speed $v$ and the steering rate (the registry's adapter turns
# $v$ into the driven left wheel's rate $v(1-k)/R$ at every step).

# %%
steer_rate = wmr.Sine(0.6, 0.125)          # amplitude 0.6 rad/s, 0.125 Hz
run = wmr.compare("tricycle", [wmr.const(1.0, ramp=0.5), steer_rate], duration=8.0)
print("worst position error:", round(run.metric("worst position error", "% of path"), 3),
      "% of path")
fig, ax = plt.subplots(figsize=(5, 4))
ax.plot(run.model["x"], run.model["y"], "r", lw=4, label="model")
ax.plot(run.sim["x"], run.sim["y"], "g", lw=1.5, label="MuJoCo")
ax.set(xlabel="x (m)", ylabel="y (m)", aspect="equal", title="tricycle, sinusoidal steering")
ax.legend()
fig.tight_layout()

# %% [markdown]
# ## Reading the wheel rates from MuJoCo
# `wmr.load` gives the compiled scene; in its default *rate* mode the controls are the
# driven wheel's rate (rad/s) and the steering rate (rad/s). Steer to about 0.4 rad, hold,
# and record both rear wheels' rates and the steering angle.

# %%
model = wmr.load("tricycle")
data = mujoco.MjData(model)
dt = model.opt.timestep
time, left, right, steer = [], [], [], []
for k in range(int(4.0 / dt)):
    t = k * dt
    data.ctrl[:] = [8.0 * min(t / 0.5, 1.0), 0.4 if t < 1.0 else 0.0]
    mujoco.mj_step(model, data)
    time.append(t)
    left.append(data.joint("rear_left_wheel").qvel[0])
    right.append(data.joint("rear_right_wheel").qvel[0])
    steer.append(data.joint("steer").qpos[0])
time, left, right, steer = map(np.asarray, (time, left, right, steer))

v_mid = tricycle.midpoint_speed_from_left(R * left[-1], steer[-1], w, ell)
_, v_right = tricycle.rear_wheel_speeds(v_mid, steer[-1], w, ell)
print(f"free right wheel: {right[-1]:.4f} rad/s in MuJoCo, {v_right / R:.4f} rad/s predicted")

fig, ax = plt.subplots(figsize=(6, 3))
ax.plot(time, left, label="left (driven)")
ax.plot(time, right, label="right (free)")
ax.set(xlabel="time (s)", ylabel="wheel rate (rad/s)")
ax.legend()
fig.tight_layout()

# %% [markdown]
# ## Exercise: the instantaneous centre from the wheel rates
# From the two rear wheels' rates alone (and the track $w$), find the distance $R_C$ of
# the ICR from the rear-axle midpoint at the end of the run above. Check it with
# `check_tricycle_icr(radius, steer)`, where `steer` is the steering angle MuJoCo reports.

# %%
my_radius = None                       # your answer, m
print(check_tricycle_icr(my_radius, steer[-1]))

# %% [markdown]
# ### A solution
# $v_R - v_L = 2vk$ and $v_R + v_L = 2v$, so $k = (v_R - v_L)/(v_R + v_L)$ and
# $R_C = w / (2k)$: the wheel radius cancels.

# %%
radius = w / 2 * (right[-1] + left[-1]) / (right[-1] - left[-1])
result = check_tricycle_icr(radius, steer[-1])
print(result)
