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
# # 3. The bicycle
#
# Two wheels: a rear wheel fixed to the body and a front wheel steered by $\phi$ relative
# to it, wheelbase $\ell$. Generalized coordinates $(x, y, \psi, \phi)$: the rear contact,
# the body's heading and the steering angle. Each wheel rolls without slip:
#
# $$ \dot x \sin\psi - \dot y\cos\psi = 0, \qquad
#    \dot x \sin(\psi+\phi) - \dot y\cos(\psi+\phi) - \ell\dot\psi\cos\phi = 0 . $$
#
# With the rear wheel's ground speed $v_r$ as input (the MuJoCo bicycle drives its rear
# wheel; the lecture's front speed is $v_f = v_r/\cos\phi$):
#
# $$ \dot x = v_r\cos\psi,\quad \dot y = v_r\sin\psi,\quad
#    \dot\psi = \frac{v_r\tan\phi}{\ell},\quad \dot\phi = \omega . $$
#
# The instantaneous centre of rotation (ICR) lies on the rear axle line, at $\ell/\tan\phi$
# from the rear contact. The lecture's bicycle is planar: the MuJoCo model is held upright
# by its joints (`models/bicycle`), and moves only through its wheels' contacts.
#
# ![the bicycle in MuJoCo](../../renders/bicycle.gif)

# %%
import matplotlib.pyplot as plt
import numpy as np

import wmr_mujoco as wmr
from wmr_mujoco.analytic import bicycle, nonholonomy
from wmr_mujoco.robots.bicycle.params import BicycleParams
from wmr_mujoco.tutorials.checks import check_parallel_park
from wmr_mujoco.tutorials.schedule import segment_inputs

ell = BicycleParams().wheelbase
print(f"wheelbase ℓ = {ell} m")

# %% [markdown]
# ## A steady turn: model, physics and the ICR
# Steer to $\phi = 0.3$ rad (steering rate 0.3 rad/s for 1 s), then hold it.

# %%
steer_rate = wmr.Piecewise([(0.0, 0.3), (1.0, 0.0)])
run = wmr.compare("bicycle", [wmr.const(2.0, ramp=0.5), steer_rate], duration=6.0)
print("worst position error:", round(run.metric("worst position error", "% of path"), 3),
      "% of path")

steady = run.sim.time > 2.0
xs, ys, psi = run.sim["x"], run.sim["y"], np.unwrap(run.sim["heading"])
speed = np.hypot(np.gradient(xs, run.sim.time), np.gradient(ys, run.sim.time))
turning_radius = np.mean(speed[steady] / np.gradient(psi, run.sim.time)[steady])
phi = np.mean(run.sim["steer"][steady])
print(f"turning radius of the rear contact, MuJoCo: {turning_radius:.4f} m;"
      f" ℓ / tan φ = {bicycle.icr_radius(phi, ell):.4f} m")

fig, ax = plt.subplots(figsize=(5, 5))
ax.plot(run.model["x"], run.model["y"], "r", lw=4, label="model")
ax.plot(xs, ys, "g", lw=1.5, label="MuJoCo")
ax.set(xlabel="x (m)", ylabel="y (m)", aspect="equal", title="steady turn")
ax.legend()
fig.tight_layout()

# %% [markdown]
# ## How many directions can the bicycle reach?
# The input fields are $g_1 = (\cos\psi, \sin\psi, \tan\phi/\ell, 0)$ (drive) and
# $g_2 = (0, 0, 0, 1)$ (steer). They span 2 of the 4 directions; their bracket
# $[g_1, g_2]$ adds a third (turning), and the brackets of that with $g_1$ the fourth:
# **sideways**. So the bicycle can move sideways, but only through a second-order cycle of
# its inputs: that is parallel parking.

# %%
def g1(q):
    return bicycle.input_fields(q, ell)[:, 0]


def g2(q):
    return bicycle.input_fields(q, ell)[:, 1]


q0 = np.array([0.0, 0.0, 0.0, 0.2])
for depth in (1, 2, 3):
    print(f"brackets up to depth {depth}: rank",
          nonholonomy.accessibility_rank([g1, g2], q0, depth=depth))

# %% [markdown]
# ## Exercise: parallel parking
# Move the MuJoCo bicycle at least 0.3 m **to its left**, ending parallel to its start
# (heading within 3°), no more than 0.1 m ahead or behind, steering straight again
# (within 0.05 rad), with four open-loop segments `(rear speed, steering rate, duration)`.
# Check the simulated trajectory with `check_parallel_park`.

# %%
my_segments = [(-1.0, 0.5, 1.0)]      # your four segments
speed, steer, duration = segment_inputs(my_segments)
print(check_parallel_park(wmr.simulate("bicycle", [speed, steer], duration)))

# %% [markdown]
# ### A solution
# Reverse along an S: steer left while reversing, then right for twice as long, then back
# to straight. The steering angle is odd about the middle, so the heading comes back; the
# bicycle ends further left and further back. A fourth segment drives straight forward by
# the distance the model predicts it lost.

# %%
s_curve = [(-1.0, 0.5, 1.0), (-1.0, -0.5, 2.0), (-1.0, 0.5, 1.0)]
speed, steer, duration = segment_inputs(s_curve)
behind = wmr.predict("bicycle", [speed, steer], duration).states
back_by = behind[0, 0] - behind[-1, 0]                  # m, along the start heading
forward = (1.0, 0.0, back_by / 1.0 + 0.3)               # trapezoid: distance = v (T − ramp)
speed, steer, duration = segment_inputs([*s_curve, forward])
park = wmr.compare("bicycle", [speed, steer], duration)
result = check_parallel_park(park.sim)
print(result)

fig, ax = plt.subplots(figsize=(6, 3))
ax.plot(park.model["x"], park.model["y"], "r", lw=4, label="model")
ax.plot(park.sim["x"], park.sim["y"], "g", lw=1.5, label="MuJoCo")
ax.set(xlabel="x (m)", ylabel="y (m)", aspect="equal", title="parallel parking (rear contact)")
ax.legend()
fig.tight_layout()
