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
# # 1. A single wheel
#
# The lecture starts with one wheel: a thin disc rolling without slipping on the floor.
# Its configuration is the contact point $(x, y)$ and the heading $\phi$ of the wheel
# plane; the inputs are the forward speed $v = R\dot\theta$ ($R$ the radius, $\theta$ the
# spin angle) and the steering rate $\omega$:
#
# $$
# \begin{pmatrix}\dot x\\ \dot y\\ \dot\phi\end{pmatrix}
# = \begin{pmatrix}\cos\phi\\ \sin\phi\\ 0\end{pmatrix} v
# + \begin{pmatrix}0\\ 0\\ 1\end{pmatrix}\omega .
# $$
#
# With constant inputs the disc drives a circle of radius $v/\omega$. Below, the same
# inputs go through this model (`wmr_mujoco.analytic.unicycle`) and through MuJoCo's
# `disc`: a thin disc on a vertical mount, moved **only** by its contact with the floor.
#
# ![the disc in MuJoCo: physics trail green, model trail red](../../renders/disc.gif)

# %%
import matplotlib.pyplot as plt
import numpy as np

import wmr_mujoco as wmr
from wmr_mujoco.analytic import unicycle, wrap_angle
from wmr_mujoco.tutorials.checks import check_circle_radius

# %% [markdown]
# ## The model
# `unicycle.rates(q, u)` is the right-hand side above; `constant_input_pose` its closed
# form for constant inputs (a circle).

# %%
q = np.array([0.0, 0.0, 0.0])          # x, y (m), heading φ (rad)
print("q̇ at rest heading 0, v = 0.5 m/s, ω = 0.4 rad/s:", unicycle.rates(q, [0.5, 0.4]))
t = np.linspace(0.0, 2 * np.pi / 0.4, 5)
print(unicycle.constant_input_pose(q, 0.5, 0.4, t).round(3))   # one lap: back to the start

# %% [markdown]
# ## The same inputs through MuJoCo
# `wmr.compare` drives the MuJoCo disc with $(v, \omega)$ (it turns them into the wheel's
# rate $v/R$ and the steering rate) and integrates the model from the same settled start
# on the same time grid. The speed ramps up over 0.5 s: a step would make a real wheel
# slip, and the kinematic model assumes it does not.

# %%
v, omega = 0.5, 0.4
run = wmr.compare("disc", [wmr.const(v, ramp=0.5), omega], duration=12.0)
for label, traj in (("physics", run.sim), ("model", run.model)):
    x, y, phi = traj.pose[-1]
    print(f"final pose, {label:8s} x = {x:.4f} m, y = {y:.4f} m, φ = {wrap_angle(phi):.4f} rad")
print("worst position error:", round(run.metric("worst position error", "% of path"), 3),
      "% of path; passed:", run.passed)

# %%
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
ax1.plot(run.model["x"], run.model["y"], "r", lw=4, label="model")
ax1.plot(run.sim["x"], run.sim["y"], "g", lw=1.5, label="MuJoCo")
ax1.set(xlabel="x (m)", ylabel="y (m)", aspect="equal", title="path")
ax1.legend()
gap = np.hypot(*(run.sim.pose[:, :2] - run.model.pose[:, :2]).T)
ax2.plot(run.sim.time, 1000 * gap)
ax2.set(xlabel="time (s)", ylabel="distance (mm)", title="physics − model")
fig.tight_layout()

# %% [markdown]
# ## Exercise: the circle's radius
# Measure the radius of the circle that the **MuJoCo** disc drives once its speed has
# settled (after the first second), and check it against $v/\omega$ with
# `check_circle_radius(radius, v, omega)`. A hint: the points of a circle satisfy
# $x^2 + y^2 + a x + b y + c = 0$, which is linear in $(a, b, c)$.

# %%
my_radius = None          # your answer, in metres
print(check_circle_radius(my_radius, v, omega))

# %% [markdown]
# ### A solution
# Fit $(a, b, c)$ by least squares; the radius is $\sqrt{a^2/4 + b^2/4 - c}$.

# %%
steady = run.sim.time > 1.0
x, y = run.sim["x"][steady], run.sim["y"][steady]
(a, b, c), *_ = np.linalg.lstsq(np.column_stack([x, y, np.ones_like(x)]), -(x**2 + y**2),
                                rcond=None)
radius = float(np.sqrt(a**2 / 4 + b**2 / 4 - c))
result = check_circle_radius(radius, v, omega)
print(result)
