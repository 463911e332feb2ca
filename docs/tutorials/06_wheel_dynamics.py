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
# # 6. The dynamics of one wheel
#
# A wheel of radius $R$ and axial inertia $J$ carries a translating mass $m$; a torque
# $\tau$ acts on its axle and the floor pushes back with a traction force $F_T$. The
# lecture's two equations:
#
# $$ m\ddot x = F_T, \qquad J\ddot\theta = \tau - F_T R . $$
#
# Rolling ($\dot x = R\dot\theta$, so $\ddot x = R\ddot\theta$) closes them:
#
# $$ \ddot x = \frac{\tau R}{J + mR^2}, \qquad F_T = m\ddot x . $$
#
# Rolling holds while the floor can supply $F_T$: $|F_T| \le \mu N$. Past that the wheel
# slips and kinetic friction $\mu N$ drives the two equations separately
# (`wmr_mujoco.analytic.wheel_dynamics`). The MuJoCo `disc` in torque mode is this wheel:
# its carriage slides freely on the mount, so $m$ is disc plus carriage.

# %%
import matplotlib.pyplot as plt
import mujoco
import numpy as np

import wmr_mujoco as wmr
from wmr_mujoco.robots.disc.wheel import mounted_wheel
from wmr_mujoco.tutorials.checks import check_traction_limit

wheel = mounted_wheel(wmr.load("disc"))     # m, J (with the motor's armature), R, μ, N
print(f"m = {wheel.mass} kg, J = {wheel.inertia:.5g} kg·m², R = {wheel.radius} m, "
      f"μ = {wheel.friction}, N = {wheel.normal:.4g} N")

# %% [markdown]
# ## A constant torque: model and physics
# `kind="dynamic"` makes the inputs axle torques (N·m): the wheel's and the steering's.
# The state is the distance and speed along the heading.

# %%
tau = 1.0
run = wmr.compare("disc", [tau, 0.0], duration=2.0, kind="dynamic")
slope = np.polyfit(run.sim.time[run.sim.time > 0.5], run.sim["speed"][run.sim.time > 0.5], 1)[0]
print(f"acceleration: MuJoCo {slope:.5f} m/s², τR/(J + mR²) = "
      f"{wheel.rolling_acceleration(tau):.5f} m/s²")

fig, ax = plt.subplots(figsize=(6, 3))
ax.plot(run.model.time, run.model["speed"], "r", lw=4, label="model")
ax.plot(run.sim.time, run.sim["speed"], "g", lw=1.5, label="MuJoCo")
ax.set(xlabel="time (s)", ylabel="speed (m/s)", title=f"τ = {tau} N·m")
ax.legend()
fig.tight_layout()

# %% [markdown]
# ## Exercise: the traction limit
# From the two equations and $|F_T| \le \mu N$, find the largest torque for which the
# wheel still rolls, with the constants of `wheel` above (without calling its
# `max_rolling_torque`). Check it with `check_traction_limit(torque, wheel)`.

# %%
my_torque = wheel.friction * wheel.normal * wheel.radius      # your answer, N·m
print(check_traction_limit(my_torque, wheel))

# %% [markdown]
# ### A solution
# $F_T = m\tau R/(J + mR^2) \le \mu N$ gives $\tau \le \mu N (J + mR^2)/(mR)$: larger
# than $\mu N R$, because part of the torque spins the wheel up.

# %%
limit = wheel.friction * wheel.normal * (wheel.inertia + wheel.mass * wheel.radius**2) / (
    wheel.mass * wheel.radius)
result = check_traction_limit(limit, wheel)
print(result)

# %% [markdown]
# ## Below and above the limit in MuJoCo
# Drive the compiled disc in torque mode at 0.9 and 1.1 times the limit for 0.5 s and
# record the slip speed $R\dot\theta - \dot x$ of the contact.

# %%
fig, ax = plt.subplots(figsize=(6, 3))
for factor in (0.9, 1.1):
    model = wmr.load("disc")
    wmr.set_actuation_mode(model, "torque")
    data = mujoco.MjData(model)
    for _ in range(int(0.3 / model.opt.timestep)):           # settle on the floor
        mujoco.mj_step(model, data)
    time, slip = [], []
    for k in range(int(0.5 / model.opt.timestep)):
        data.ctrl[:] = [factor * limit, 0.0]
        mujoco.mj_step(model, data)
        time.append(k * model.opt.timestep)
        slip.append(wheel.radius * data.joint("wheel").qvel[0] - data.joint("mount_x").qvel[0])
    ax.plot(time, 1000 * np.asarray(slip), label=f"{factor} × limit")
    print(f"{factor} × limit: slip speed after 0.5 s {1000 * slip[-1]:.2f} mm/s")
ax.set(xlabel="time (s)", ylabel="slip speed (mm/s)", title="rolling, then sliding")
ax.legend()
fig.tight_layout()
