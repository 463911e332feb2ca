"""The free disc in MuJoCo in the rolling-disc terms of :mod:`wmr_mujoco.analytic.rolling_disc`.

Constants from the compiled model, the analytic state put into MuJoCo, the MuJoCo state
read back as contact point, heading, lean, tilted-frame angular velocity and energy, and
one run from an analytic state (:class:`FreeRun`), shared by the measurements and the
clips.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.analytic.rolling_disc import RollingDisc
from wmr_mujoco.sim.stepping import check_healthy

#: Columns of :func:`run`'s rows after the time.
POSE_NAMES = ("x_P", "y_P", "heading", "lean", "w1", "w2", "w3", "energy")


def disc_from_model(model: mujoco.MjModel) -> RollingDisc:
    """Thin-disc constants of the compiled free disc: mass, inertias, radius, gravity."""
    b = model.body("disc").id
    inertia = model.body_inertia[b]
    return RollingDisc(radius=float(model.geom("disc_collision").size[0]),
                       mass=float(model.body_mass[b]), axial_inertia=float(inertia[1]),
                       diametral_inertia=float(inertia[0]),
                       gravity=float(np.linalg.norm(model.opt.gravity)))


def set_free_state(model: mujoco.MjModel, data: mujoco.MjData, disc: RollingDisc,
                   state: np.ndarray) -> None:
    """Put the free disc on the analytic ``state`` (spin angle 0), touching the floor.

    Orientation ``R = R_z(ψ) R_x(θ)`` (body x = ê1, y = axle ê2, z = ê3); centre height
    the collision ellipsoid's support ``√(a² cos² θ + b² sin² θ)`` (cylinder:
    ``a cos θ + b |sin θ|``); linear velocity ``v_G = a (ω2 ê1 − ω1 ê2)``; body angular
    velocity ``(ω1, ω2, ω3)``.
    """
    mujoco.mj_resetData(model, data)
    psi, th = state[2], state[3]
    quat = np.zeros(4)
    mujoco.mju_mulQuat(quat, np.array([math.cos(psi / 2), 0, 0, math.sin(psi / 2)]),
                       np.array([math.cos(th / 2), math.sin(th / 2), 0, 0]))
    geom = model.geom("disc_collision")
    a, b = geom.size[:2]
    centre = disc.centre(state)
    if geom.type[0] == mujoco.mjtGeom.mjGEOM_CYLINDER:
        centre[2] = a * math.cos(th) + b * abs(math.sin(th))  # the rim edge touches
    else:
        centre[2] = math.hypot(a * math.cos(th), b * math.sin(th))
    data.qpos[:3] = centre
    data.qpos[3:7] = quat
    data.qvel[:3] = disc.centre_velocity(state)
    data.qvel[3:6] = state[5:8]
    mujoco.mj_forward(model, data)


def free_pose(model: mujoco.MjModel, data: mujoco.MjData, radius: float) -> np.ndarray:
    """``(x_P, y_P, ψ, θ, ω1, ω2, ω3, E)`` of the free disc now.

    Axle ê2 = body y; lean ``θ = asin(ê2_z)``; ê1 = ê2 × ẑ normalised; contact point
    ``P = G − a ê3`` (the thin-disc contact); ω in the tilted frame; energy
    ``E = ½ m v² + ½ ωᵀ I ω + m g z_G``.
    """
    b = model.body("disc").id
    rot = data.xmat[b].reshape(3, 3)
    e2 = rot[:, 1]
    z = float(e2[2])  # np.clip's float (a NaN kept) without its per-call cost
    th = math.asin(z if z != z else min(1.0, max(-1.0, z)))
    e1 = _cross(e2.tolist(), (0.0, 0.0, 1.0))
    e1 /= np.linalg.norm(e1)
    e3 = _cross(e1.tolist(), e2.tolist())
    p = data.xpos[b] - radius * e3
    w_world = rot @ data.qvel[3:6]
    m = model.body_mass[b]
    g = -model.opt.gravity
    energy = (0.5 * m * data.qvel[:3] @ data.qvel[:3]
              + 0.5 * data.qvel[3:6] @ (model.body_inertia[b] * data.qvel[3:6])
              + m * g @ data.xpos[b])
    return np.array([p[0], p[1], math.atan2(e1[1], e1[0]), th, w_world @ e1,
                     w_world @ e2, w_world @ e3, energy])


def _cross(a: list[float], b: tuple[float, ...] | list[float]) -> np.ndarray:
    """``np.cross(a, b)`` of two 3-vectors, its floats at a tenth of its cost.

    ``(a₁b₂ − a₂b₁, a₂b₀ − a₀b₂, a₀b₁ − a₁b₀)`` as numpy evaluates them: one rounding per
    product and per difference.
    """
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                     a[0] * b[1] - a[1] * b[0]])


@dataclass(frozen=True)
class FreeRun:
    """One run of the free disc from an analytic state.

    Attributes:
        model: the compiled free disc (a measurement may change its gravity: an incline).
        state: analytic initial state (:data:`~wmr_mujoco.analytic.rolling_disc.STATE_NAMES`).
        duration: seconds to run.
        stop: ends the run early when it returns True for a row ``(t, pose...)``.
    """

    model: mujoco.MjModel
    state: np.ndarray
    duration: float
    stop: Callable[[np.ndarray], bool] | None = None

    @property
    def disc(self) -> RollingDisc:
        """The analytic disc of the model."""
        return disc_from_model(self.model)

    def steps(self) -> Iterator[tuple[mujoco.MjData, np.ndarray]]:
        """The simulation and its row ``(t, free_pose...)`` at the start and after each step.

        Raises:
            SimulationDivergedError: the run diverged.
        """
        model = self.model
        disc = self.disc
        data = mujoco.MjData(model)
        set_free_state(model, data, disc, self.state)
        n = round(self.duration / model.opt.timestep)
        for k in range(n + 1):
            if k:
                mujoco.mj_step(model, data)
            row = np.empty(1 + len(POSE_NAMES))
            row[0], row[1:] = data.time, free_pose(model, data, disc.radius)
            yield data, row
            if k and self.stop is not None and self.stop(row):
                break
        check_healthy(model, data)

    def rows(self) -> np.ndarray:
        """Rows ``(t, x_P, y_P, ψ, θ, ω1, ω2, ω3, E)`` of the whole run."""
        return np.array([row for _, row in self.steps()])
