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
# # 2. The non-holonomic constraint
#
# Rolling without slip forbids any velocity across the wheel plane:
#
# $$ \dot x \sin\phi - \dot y \cos\phi = 0 . $$
#
# The lecture calls this constraint **non-holonomic**: it restricts velocities, and no
# function $f(x, y, \phi) = 0$ of the configuration integrates it. Its argument: if such an
# $f$ existed, fixing $(x, y)$ would fix $\phi$; yet the disc can be turned about its
# vertical at any point, so every $\phi$ is reachable at every $(x, y)$.
#
# This page measures the constraint on the MuJoCo disc, shows the direction it forbids
# with a Lie bracket (`wmr_mujoco.analytic.nonholonomy`), and moves the disc sideways
# (the forbidden direction) using allowed motions only.

# %%
import matplotlib.pyplot as plt
import numpy as np

import wmr_mujoco as wmr
from wmr_mujoco.analytic import nonholonomy, unicycle
from wmr_mujoco.tutorials.checks import check_closed_loop
from wmr_mujoco.tutorials.schedule import segment_inputs

# %% [markdown]
# ## The constraint along a MuJoCo run
# Drive the disc with a sinusoidal steering rate and evaluate
# $\dot x \sin\phi - \dot y\cos\phi$ along the simulated path: it is the contact's speed
# across the wheel plane, the lateral slip.

# %%
run = wmr.simulate("disc", [wmr.const(0.5, ramp=0.5), wmr.Sine(0.8, 0.25)], duration=8.0)
x, y, phi = run.pose.T
xdot, ydot = np.gradient(x, run.time), np.gradient(y, run.time)
lateral = xdot * np.sin(phi) - ydot * np.cos(phi)
forward = xdot * np.cos(phi) + ydot * np.sin(phi)
print(f"largest |lateral speed|: {1000 * np.max(np.abs(lateral)):.3f} mm/s "
      f"(forward speed up to {np.max(forward):.2f} m/s)")

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 3.5))
ax1.plot(x, y)
ax1.set(xlabel="x (m)", ylabel="y (m)", aspect="equal", title="path (MuJoCo)")
ax2.plot(run.time, 1000 * lateral)
ax2.set(xlabel="time (s)", ylabel="mm/s", title=r"$\dot x\sin\phi-\dot y\cos\phi$")
fig.tight_layout()

# %% [markdown]
# ## The Lie bracket: the direction the inputs do not span
# The input fields are $g_1 = (\cos\phi, \sin\phi, 0)$ (roll) and $g_2 = (0, 0, 1)$ (turn).
# Their Lie bracket $[g_1, g_2] = Dg_2\,g_1 - Dg_1\,g_2 = (\sin\phi, -\cos\phi, 0)$ points
# sideways, exactly the direction the constraint forbids. With it the three fields span all
# of $(x, y, \phi)$: by Frobenius' theorem no $f(x, y, \phi) = 0$ exists, and by Chow's
# every configuration can be reached.

# %%
def g1(q):
    return unicycle.input_fields(q)[:, 0]


def g2(q):
    return unicycle.input_fields(q)[:, 1]


q0 = np.array([0.0, 0.0, 0.3])
print("[g1, g2] at φ = 0.3:", nonholonomy.lie_bracket(g1, g2, q0).round(6),
      " (sin φ, −cos φ, 0) =", np.round([np.sin(0.3), -np.cos(0.3), 0.0], 6))
print("rank of g1, g2:", nonholonomy.accessibility_rank([g1, g2], q0, depth=1),
      "  with their bracket:", nonholonomy.accessibility_rank([g1, g2], q0, depth=2))

# %% [markdown]
# ## Moving sideways with allowed motions
# The cycle "forward $d$, turn $\Delta$, back $d$, turn back" moves the disc, in its start
# frame, by $(d(1-\cos\Delta),\, -d\sin\Delta)$: sideways, with its heading restored.
# `segment_inputs` turns segments `(speed, steering rate, duration)` into input
# functions, each segment's speed ramped up and down over 0.3 s.

# %%
turn_rate, turn_time = 1.0, 0.5                    # Δ = 0.5 rad
speed, steer, duration = segment_inputs(
    [(0.5, 0.0, 2.3), (0.0, turn_rate, turn_time), (-0.5, 0.0, 2.3),
     (0.0, -turn_rate, turn_time)])
cycle = wmr.compare("disc", [speed, steer], duration)
d = 0.5 * (2.3 - 0.3)                                # distance of a trapezoid segment
start, end = cycle.sim.pose[0], cycle.sim.pose[-1]
print("predicted (d(1 − cos Δ), −d sin Δ):",
      nonholonomy.unicycle_cycle_displacement(d, turn_rate * turn_time).round(4))
print("MuJoCo:                           ", (end[:2] - start[:2]).round(4),
      f" heading change {np.degrees(end[2] - start[2]):.2f}°")

# %% [markdown]
# ## Exercise: a closed loop that changes the heading
# Show that the constraint cannot be integrated: drive the MuJoCo disc around a closed
# loop in $(x, y)$, at least 0.5 m long, that brings it back to its start (within 2 % of
# the path) with its heading changed (by more than 5°). Build the loop from segments and
# pass the simulated trajectory to `check_closed_loop`.

# %%
my_segments = [(0.5, 0.0, 2.0)]      # your loop: (speed m/s, steering rate rad/s, s)
speed, steer, duration = segment_inputs(my_segments)
print(check_closed_loop(wmr.simulate("disc", [speed, steer], duration)))

# %% [markdown]
# ### A solution
# Three equal sides of a triangle, turning by 120° on the spot between them: back at the
# start, facing 240° from where it started.

# %%
side = (0.5, 0.0, 2.0)
pivot = (0.0, 1.0, 2 * np.pi / 3)            # 1 rad/s for 2π/3 s: 120°
speed, steer, duration = segment_inputs([side, pivot, side, pivot, side])
loop = wmr.simulate("disc", [speed, steer], duration)
result = check_closed_loop(loop)
print(result)

fig, ax = plt.subplots(figsize=(4, 4))
ax.plot(loop["x"], loop["y"])
ax.plot(*loop.pose[0, :2], "go", label="start")
ax.plot(*loop.pose[-1, :2], "rx", label="end")
ax.set(xlabel="x (m)", ylabel="y (m)", aspect="equal", title="a closed loop")
ax.legend()
fig.tight_layout()
