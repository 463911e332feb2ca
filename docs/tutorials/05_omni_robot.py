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
# # 5. The omni robot
#
# Three omni (Swedish) wheels at 120°, at distance $L$ from the centre, radius $r$, no
# steering. Free, unactuated barrels (rollers) on each rim let a wheel slide along its
# axle, so each wheel constrains only the velocity along its own rolling direction. The
# lecture's kinematics:
#
# $$
# \begin{pmatrix}\dot\theta_1\\ \dot\theta_2\\ \dot\theta_3\end{pmatrix}
# = \frac{1}{r}\begin{bmatrix} 0 & 1 & L\\ -\sqrt3/2 & -1/2 & L\\ \sqrt3/2 & -1/2 & L
# \end{bmatrix} \nu .
# $$
#
# $J$ is constant, which holds only if $\nu = (u, v, r)$ is the platform's velocity in
# **its own frame** (forward, left, yaw rate); world rates are
# $(\dot X, \dot Y) = \mathrm{Rot}(\psi)(u, v)$ (`wmr_mujoco.robots.roller_wheels.omni_kinematics`).
# Wheel 1 sits on the body's $x$ axis and rolls along $+y$. The MuJoCo `omni3` has two
# staggered rows of six rollers per wheel, as the lecture describes, every roller a free
# hinge.
#
# ![omni3 in MuJoCo](../../renders/omni3.gif)

# %%
import matplotlib.pyplot as plt
import mujoco
import numpy as np

import wmr_mujoco as wmr
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.tutorials.checks import check_omni_wheel_rates

p = OmniParams()
r_w, L = p.wheel_radius, p.wheel_distance
H = ok.wheel_jacobian(ok.symmetric_layout(r_w, L))      # θ̇ = H ν
print(f"r = {r_w} m, L = {L} m;  r H = J =\n{(r_w * H).round(4)}")

# %% [markdown]
# ## A twist through model and physics
# `wmr.compare("omni3", (u, v, r))` turns the body twist into wheel rates $H\nu$ at every
# step (the wheels are rate-servoed), and integrates the kinematic model beside it.

# %%
ramp = 0.5
twist = [wmr.const(0.2, ramp=ramp), wmr.const(0.1, ramp=ramp), wmr.const(0.6, ramp=ramp)]
run = wmr.compare("omni3", twist, duration=4.0)
print("worst position error:", round(run.metric("worst position error", "% of path"), 3),
      "% of path; worst heading error:",
      round(run.metric("worst heading error", "deg"), 3), "°")

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
ax1.plot(run.model["x"], run.model["y"], "r", lw=4, label="model")
ax1.plot(run.sim["x"], run.sim["y"], "g", lw=1.5, label="MuJoCo")
ax1.set(xlabel="X (m)", ylabel="Y (m)", aspect="equal", title="translate while turning")
ax1.legend()
ax2.plot(run.sim.time, np.degrees(np.unwrap(run.sim["heading"]) - run.model["heading"]))
ax2.set(xlabel="time (s)", ylabel="°", title="heading, physics − model")
fig.tight_layout()

# %% [markdown]
# The heading error ripples: the two roller rows touch the floor in turn, at $L \pm e$
# from the centre rather than at $L$, as the lecture remarks (`models/omni3/README.md`
# measures it).
#
# ## Exercise: wheel rates for a sideways glide
# Compute the three wheel rates (rad/s) that move the platform at 0.2 m/s along the
# direction 45° to the left of its $x$ axis, without turning, from the lecture's matrix.
# Check them with `check_omni_wheel_rates(rates, twist)`, then drive MuJoCo with them.

# %%
glide = np.array([0.2 * np.cos(np.pi / 4), 0.2 * np.sin(np.pi / 4), 0.0])   # (u, v, r)
my_rates = [0.0, 0.0, 0.0]          # your answer, rad/s
print(check_omni_wheel_rates(my_rates, glide))

# %% [markdown]
# ### A solution

# %%
J = np.array([[0.0, 1.0, L], [-np.sqrt(3) / 2, -0.5, L], [np.sqrt(3) / 2, -0.5, L]])
rates = J @ glide / r_w
result = check_omni_wheel_rates(rates, glide)
print(result)

# %% [markdown]
# Drive the compiled model with these rates as wheel-rate commands (ramped over 0.5 s) and
# measure the direction of travel and the turn.

# %%
model = wmr.load("omni3")
data = mujoco.MjData(model)
dt = model.opt.timestep
poses = []
for k in range(int(2.5 / dt)):
    data.ctrl[:] = rates * min(k * dt / 0.5, 1.0)
    mujoco.mj_step(model, data)
    poses.append(wmr.base_pose(model, data))
poses = np.asarray(poses)
moved = poses[-1, :2] - poses[int(1.0 / dt), :2]          # the last 1.5 s, at full speed
print(f"direction of travel: {np.degrees(np.arctan2(moved[1], moved[0])):.2f}° "
      f"(asked 45°), speed {np.hypot(*moved) / 1.5:.4f} m/s (asked 0.2), "
      f"heading change {np.degrees(poses[-1, 2] - poses[0, 2]):.3f}°")
