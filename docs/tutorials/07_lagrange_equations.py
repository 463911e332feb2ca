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
# # 7. The omni robot's Lagrange equations
#
# The lecture ends with the equations of motion of the three-wheeled omni robot, from the
# kinetic energy of the platform and the wheels (no potential energy on a flat floor):
#
# $$
# \begin{bmatrix} M_p & 0 & 0\\ 0 & M_p & 0\\ 0 & 0 & I_p\end{bmatrix}\dot\nu
# + \dot\psi\begin{bmatrix} 0 & -M_p & 0\\ M_p & 0 & 0\\ 0 & 0 & 0\end{bmatrix}\nu
# = r R^T F_t, \qquad
# \begin{bmatrix} I_1 & 0 & 0\\ 0 & I_2 & 0\\ 0 & 0 & I_3\end{bmatrix}\ddot\theta
# + r F_t = \tau ,
# $$
#
# and invites: *"you can try simulating these expressions"*. Three points the slide leaves
# open are settled in `docs/analytical.md` §6: $\nu = (u, v, r)$ is the **body-frame**
# twist (the $\dot\psi = r$ matrix is the rigid-body term of body-frame velocities);
# $R$ is the wheel Jacobian $H = J/r$ of page 5, not a rotation; and the traction forces
# $F_t$ are eliminated with $\ddot\theta = H\dot\nu$ (exact in the body frame), which gives
#
# $$ \big(\mathrm{diag}(M, M, I_z) + I_w H^T H\big)\dot\nu + r\,(-M v,\ M u,\ 0)^T
#    = H^T\tau . $$
#
# $M$ and $I_z$ are the whole robot's mass and yaw inertia, $I_w$ each wheel's spin
# inertia; below they are read from the compiled MuJoCo model.

# %%
import matplotlib.pyplot as plt
import mujoco
import numpy as np

import wmr_mujoco as wmr
from wmr_mujoco.analytic import rk4_step
from wmr_mujoco.tutorials.checks import check_omni_equations, omni_dynamics

dyn = omni_dynamics()                     # M, I_z, I_w read from the compiled omni3
M, I_z, I_w = dyn.mass, dyn.yaw_inertia, dyn.wheel_inertia
r_w, L = float(dyn.layout.radii[0]), float(np.hypot(*dyn.layout.positions[0]))
print(f"M = {M:.4g} kg, I_z = {I_z:.4g} kg·m², I_w = {I_w:.4g} kg·m², "
      f"r = {r_w:.4g} m, L = {L:.4g} m")

# %% [markdown]
# ## Exercise: simulate the lecture's equations
# Write `f(nu, tau)` returning $\dot\nu$ from the lecture's matrices (build $M_p$, the
# $\dot\psi$ matrix, $R = J/r$ and the wheel equation yourself, then eliminate $F_t$).
# `check_omni_equations(f)` tries it at a few states: first without rotation (mass matrix
# and input), then without torque (the $\dot\psi$ term), then in general.

# %%
def my_f(nu, tau):
    """Your equations of motion: ν̇ = f(ν, τ)."""
    return np.zeros(3)


print(check_omni_equations(my_f))

# %% [markdown]
# ### A solution

# %%
J = np.array([[0.0, 1.0, L], [-np.sqrt(3) / 2, -0.5, L], [np.sqrt(3) / 2, -0.5, L]])
H = J / r_w                                              # the slide's R
M_p = np.diag([M, M, I_z])


def f(nu, tau):
    """ν̇ from M_p ν̇ + ψ̇ C ν = r Hᵀ F_t and I_w θ̈ + r F_t = τ with θ̈ = H ν̇."""
    C = nu[2] * np.array([[0.0, -M, 0.0], [M, 0.0, 0.0], [0.0, 0.0, 0.0]])
    # r F_t = τ − I_w H ν̇  ⇒  (M_p + I_w HᵀH) ν̇ = Hᵀ τ − C ν
    return np.linalg.solve(M_p + I_w * H.T @ H, H.T @ tau - C @ nu)


result = check_omni_equations(f)
print(result)

# %% [markdown]
# ## The equations against the physics
# Constant wheel torques from rest: $\tau = (0, -0.05, 0.05)$ N·m pushes the platform
# along its $x$ axis. The compiled model in torque mode settles on its rollers first; then
# both the physics and the equations (RK4 on the same time step) run for 1.5 s from the
# same twist.

# %%
tau = np.array([0.0, -0.05, 0.05])
model = wmr.load("omni3")
wmr.set_actuation_mode(model, "torque")
data = mujoco.MjData(model)
dt = model.opt.timestep
for _ in range(int(0.5 / dt)):                           # settle, no torque
    mujoco.mj_step(model, data)
n = int(1.5 / dt)
sim = np.zeros((n + 1, 3))
sim[0] = wmr.body_twist(model, data)
for k in range(n):
    data.ctrl[:] = tau
    mujoco.mj_step(model, data)
    sim[k + 1] = wmr.body_twist(model, data)
lagrange = np.zeros((n + 1, 3))
lagrange[0] = sim[0]
for k in range(n):
    lagrange[k + 1] = rk4_step(f, lagrange[k], tau, dt)
time = np.arange(n + 1) * dt
print(f"u after 1.5 s: MuJoCo {sim[-1, 0]:.4f} m/s, equations {lagrange[-1, 0]:.4f} m/s "
      f"({100 * (sim[-1, 0] / lagrange[-1, 0] - 1):+.2f} %)")

fig, ax = plt.subplots(figsize=(6, 3))
for i, name in enumerate(["u (m/s)", "v (m/s)", "r (rad/s)"]):
    ax.plot(time, lagrange[:, i], lw=4, alpha=0.5, label=f"{name}, equations")
    ax.plot(time, sim[:, i], lw=1, label=f"{name}, MuJoCo")
ax.set(xlabel="time (s)", title="constant torques from rest")
ax.legend(fontsize=7)
fig.tight_layout()

# %% [markdown]
# The small remaining difference is what the slide leaves out: the rollers' own inertia
# and the jumps of the wheel speeds when the contact passes from one roller row to the
# other. The hybrid model of `docs/omni-dynamics.md` adds both.
