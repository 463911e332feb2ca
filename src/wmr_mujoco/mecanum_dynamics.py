"""``mecanum4`` under wheel torques against the reduced Lagrange equations of the omni platform.

:class:`wmr_mujoco.analytic.omni_dynamics.OmniDynamics` holds for any wheel Jacobian H,
mecanum included (the derivation only uses ``θ̇ = H ν`` and the virtual power
``τᵀ θ̇``)::

    (diag(M, M, I_z) + I_w HᵀH) ν̇ + r [−M v, M u, 0]ᵀ = Hᵀ τ

With four wheels and rank-3 H, torques along the left null vector of H (``Hᵀ n = 0``,
``n ∝ (1, −1, −1, 1)``) only load the rollers against each other. Rollers' own spin
inertia is neglected, as for omni3. Target: body-velocity error after 2 s within the
omni robot's 3 % (issue 5, a requirement), judged over the run (worst after the first
0.5 s, when the speeds are still small, and final).

Status: straight-ahead torques meet the target; torques that drive sideways or turn the
chassis leave it slower than the reduced model (several %, more at small torques). A
likely cause, not yet quantified: at each roller hand-over the contact jumps along the
axle by ``2 d tan(π/n) tan γ`` (docs/mecanum.md §2), so in a turn the rim speed the
contact needs jumps too and the wheel's (armature-dominated) inertia takes an impact; the
reduced model has no such loss. Not in the validation until explained.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.actuation import set_actuation_mode
from wmr_mujoco.adapters import base_pose, body_twist
from wmr_mujoco.analytic.integrate import integrate
from wmr_mujoco.analytic.omni_dynamics import OmniDynamics
from wmr_mujoco.builders.mecanum4 import WHEEL_NAMES
from wmr_mujoco.mecanum_scenarios import Row, layout
from wmr_mujoco.params_mecanum import MecanumParams
from wmr_mujoco.simulation import check_healthy

#: Requirement (issue 5, the omni robot's): body-velocity error in % after 2 s of torques.
VELOCITY_PCT = 3.0
#: A torque input that moves in all three directions, N·m per wheel (FL, FR, RL, RR).
STANDARD_TORQUES = (0.04, -0.01, 0.03, 0.0)


def dynamics_from_model(model: mujoco.MjModel, params: MecanumParams) -> OmniDynamics:
    """Lagrange-model parameters read from the compiled model.

    ``M``: total mass; ``I_z``: composite yaw inertia about the chassis centre; ``I_w``:
    wheel FL's inertia about its axle (hub and rollers, with parallel-axis terms) plus the
    hinge armature: ``I = Σ_b (aᵀ R_b I_b R_bᵀ a + m_b |r_b⊥|²)``.
    """
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    centre = data.xpos[model.body("chassis").id]

    def inertia_about(bodies: list[int], point: np.ndarray, axis: np.ndarray) -> float:
        total = 0.0
        for b in bodies:
            rot = data.ximat[b].reshape(3, 3)
            inertia = rot @ np.diag(model.body_inertia[b]) @ rot.T
            r = data.xipos[b] - point
            r_perp = r - axis * (r @ axis)
            total += axis @ inertia @ axis + model.body_mass[b] * (r_perp @ r_perp)
        return float(total)

    robot = list(range(1, model.nbody))
    wheel = model.joint(WHEEL_NAMES[0])
    wheel_body = int(wheel.bodyid[0])
    subtree = [b for b in robot if b == wheel_body or model.body_parentid[b] == wheel_body]
    i_w = inertia_about(subtree, data.xanchor[wheel.id], data.xaxis[wheel.id]) + float(
        model.dof_armature[model.jnt_dofadr[wheel.id]])
    return OmniDynamics(mass=float(sum(model.body_mass[robot])),
                        yaw_inertia=inertia_about(robot, centre, np.array([0.0, 0.0, 1.0])),
                        wheel_inertia=i_w, layout=layout(params))


@dataclass(frozen=True)
class MecanumDynamicsAdapter:
    """Adapter for the runner: ``x = (X, Y, ψ, u, v, r)``, controls = wheel torques."""

    dynamics: OmniDynamics
    robot: str = "mecanum4"
    mode: str = "torque"
    state_names: tuple[str, ...] = ("x", "y", "heading", "u", "v", "r")
    wheel_joints: tuple[str, ...] = WHEEL_NAMES
    lateral_wheels: tuple[str, ...] = ()

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """The torques themselves."""
        return np.asarray(u, float)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Reduced Lagrange equations with the world pose."""
        return self.dynamics.state_derivative(x, u)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose and body twist of the ``base`` site."""
        return np.concatenate([base_pose(model, data), body_twist(model, data)])


def run_torques(model: mujoco.MjModel, params: MecanumParams,
                torques: tuple[float, ...] = STANDARD_TORQUES, duration: float = 2.0,
                settle: float = 0.5) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Constant wheel torques from rest (after a settle in rate mode at zero rate).

    The model is switched to torque mode for the run and back to rate mode after it.

    Returns:
        ``(time, sim, analytic)``: (K+1,), and (K+1, 6) states ``(X, Y, ψ, u, v, r)``.

    Raises:
        ValueError: not four torques, or a non-positive duration.
        SimulationDivergedError: NaN or MuJoCo warnings.
    """
    tau = np.asarray(torques, float)
    if tau.shape != (4,) or not np.isfinite(tau).all():
        raise ValueError(f"torques = {torques!r}; need four finite wheel torques (FL FR RL RR)")
    if not 0.0 < duration <= 20.0:
        raise ValueError(f"duration = {duration!r} s; valid range is (0, 20]")
    adapter = MecanumDynamicsAdapter(dynamics_from_model(model, params))
    acts = np.array([model.actuator(n).id for n in WHEEL_NAMES])
    data = mujoco.MjData(model)
    dt = model.opt.timestep
    for _ in range(round(settle / dt)):
        mujoco.mj_step(model, data)
    set_actuation_mode(model, "torque")
    try:
        nstep = round(duration / dt)
        sim = np.empty((nstep + 1, 6))
        sim[0] = adapter.sim_state(model, data)
        for k in range(nstep):
            data.ctrl[acts] = tau
            mujoco.mj_step(model, data)
            sim[k + 1] = adapter.sim_state(model, data)
        check_healthy(model, data)
    finally:
        set_actuation_mode(model, "rate")
    analytic = integrate(adapter.rhs, sim[0], np.tile(tau, (nstep, 1)), dt)
    return dt * np.arange(nstep + 1), sim, analytic


def judge_torques(time: np.ndarray, sim: np.ndarray, analytic: np.ndarray) -> list[Row]:
    """Body-velocity error ``|ν_sim − ν_an| / |ν_an|`` in %, worst after 0.5 s and final.

    Angular rate enters as ``r · (a + w)``-free raw rad/s beside m/s, as in the omni
    validation (``|ν|`` of ``(u, v, r)``).
    """
    req = "requirement (issue 5, omni target)"
    err = np.linalg.norm(sim[:, 3:] - analytic[:, 3:], axis=1)
    ref = np.linalg.norm(analytic[:, 3:], axis=1)
    late = time >= 0.5
    rel = 100.0 * err[late] / ref[late]
    return [("body velocity error, worst after 0.5 s", float(rel.max()), "%", VELOCITY_PCT, req),
            ("body velocity error, final", float(rel[-1]), "%", VELOCITY_PCT, req)]
