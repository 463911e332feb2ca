"""The free disc in MuJoCo in the rolling-disc terms of :mod:`wmr_mujoco.analytic.rolling_disc`.

Constants from the compiled model, the analytic state put into MuJoCo, the MuJoCo state
read back as contact point, heading, lean, tilted-frame angular velocity and energy, and
one run from an analytic state (:class:`FreeRun`), shared by the measurements and the
clips.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
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


class _Readout:
    """:func:`free_pose` of one simulation at every step, with a time column in front.

    The model's constants (the disc's body, ``½ m``, the weight ``m g``) and views into
    ``data`` are taken once; each call evaluates :func:`free_pose`'s formulas on them in
    the same order (the same numpy and ``math`` calls), so the same floats.
    """

    def __init__(self, model: mujoco.MjModel, data: mujoco.MjData, radius: float) -> None:
        b = model.body("disc").id
        m = model.body_mass[b]
        self.data, self.radius = data, radius
        self.rot = data.xmat[b].reshape(3, 3)
        self.e2 = self.rot[:, 1]
        self.pos, self.v, self.w = data.xpos[b], data.qvel[:3], data.qvel[3:6]
        self.half_m, self.inertia, self.weight = 0.5 * m, model.body_inertia[b], m * (
            -model.opt.gravity)

    def __call__(self) -> np.ndarray:
        """``(t, x_P, y_P, ψ, θ, ω1, ω2, ω3, E)`` now."""
        e2, v, w = self.e2, self.v, self.w
        z = float(e2[2])
        th = math.asin(z if z != z else min(1.0, max(-1.0, z)))
        e1 = _cross(e2.tolist(), (0.0, 0.0, 1.0))
        e1 /= math.sqrt(e1.dot(e1))  # np.linalg.norm's floats: sqrt(x·x)
        e3 = _cross(e1.tolist(), e2.tolist())
        p = self.pos - self.radius * e3
        w_world = self.rot @ w
        energy = (self.half_m * v @ v + 0.5 * w @ (self.inertia * w) + self.weight @ self.pos)
        return np.array([self.data.time, p[0], p[1], math.atan2(e1[1], e1[0]), th,
                         w_world @ e1, w_world @ e2, w_world @ e3, energy])


def _poses(model: mujoco.MjModel, radius: float, raw: np.ndarray) -> np.ndarray:
    """:class:`_Readout`'s rows of many steps at once from their ``raw`` (N, 19) states.

    ``raw`` rows: time, the disc's ``xmat`` (9), ``xpos`` (3), ``qvel`` (6). Each step's
    floats are :func:`free_pose`'s: the elementwise steps the same operations in the same
    order, ``asin`` and ``atan2`` the ``math`` ones, and every product a stacked
    ``matmul`` whose slices have the layout of the step's own operands (numpy calls BLAS
    on each slice: ``gemv`` for ``R ω``, ``dot`` for two vectors, ``e2`` a column of ``R``
    with its stride).
    """
    b = model.body("disc").id
    m = model.body_mass[b]
    n = len(raw)
    rot = np.ascontiguousarray(raw[:, 1:10]).reshape(n, 3, 3)
    e2 = rot[:, :, 1]
    pos, v, w = (np.ascontiguousarray(raw[:, k:k + 3]) for k in (10, 13, 16))

    def dot(a: np.ndarray, c: np.ndarray) -> np.ndarray:
        return (a[:, None, :] @ c[:, :, None])[:, 0, 0]

    z = e2[:, 2].tolist()
    th = [math.asin(x if x != x else min(1.0, max(-1.0, x))) for x in z]
    e1 = np.empty((n, 3))  # e2 × (0, 0, 1), as _cross evaluates it
    e1[:, 0] = e2[:, 1] * 1.0 - e2[:, 2] * 0.0
    e1[:, 1] = e2[:, 2] * 0.0 - e2[:, 0] * 1.0
    e1[:, 2] = e2[:, 0] * 0.0 - e2[:, 1] * 0.0
    e1 /= np.sqrt(dot(e1, e1))[:, None]
    e3 = np.empty((n, 3))  # e1 × e2
    e3[:, 0] = e1[:, 1] * e2[:, 2] - e1[:, 2] * e2[:, 1]
    e3[:, 1] = e1[:, 2] * e2[:, 0] - e1[:, 0] * e2[:, 2]
    e3[:, 2] = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]
    p = pos - radius * e3
    w_world = (rot @ w[:, :, None])[:, :, 0]
    energy = (dot(0.5 * m * v, v) + dot(0.5 * w, model.body_inertia[b] * w)
              + dot(np.broadcast_to(m * -model.opt.gravity, (n, 3)), pos))
    heading = [math.atan2(y, x) for x, y in e1[:, :2].tolist()]
    return np.column_stack([raw[:, 0], p[:, 0], p[:, 1], heading, th, dot(w_world, e1),
                            dot(w_world, e2), dot(w_world, e3), energy])


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
        stop_lean: ends the run at the first step where ``|θ|`` passes it, rad (None:
            the whole duration).

    Raises:
        ValueError: a ``stop_lean`` that is not a finite number > 0.
    """

    model: mujoco.MjModel
    state: np.ndarray
    duration: float
    stop_lean: float | None = None

    def __post_init__(self) -> None:
        s = self.stop_lean
        if s is not None and not (isinstance(s, (int, float)) and math.isfinite(s) and s > 0):
            raise ValueError(f"stop_lean = {s!r} rad; valid: None or a finite number > 0")

    @property
    def disc(self) -> RollingDisc:
        """The analytic disc of the model."""
        return disc_from_model(self.model)

    def _start(self) -> tuple[mujoco.MjModel, RollingDisc, mujoco.MjData, int]:
        """The model, its disc, data at the start state, and the run's step count."""
        disc = self.disc
        data = mujoco.MjData(self.model)
        set_free_state(self.model, data, disc, self.state)
        return self.model, disc, data, round(self.duration / self.model.opt.timestep)

    def steps(self) -> Iterator[tuple[mujoco.MjData, np.ndarray]]:
        """The simulation and its row ``(t, free_pose...)`` at the start and after each step.

        Raises:
            SimulationDivergedError: the run diverged.
        """
        model, disc, data, n = self._start()
        readout = _Readout(model, data, disc.radius)
        for k in range(n + 1):
            if k:
                mujoco.mj_step(model, data)
            row = readout()
            yield data, row
            if k and self.stop_lean is not None and abs(row[4]) > self.stop_lean:
                break
        check_healthy(model, data)

    def rows(self) -> np.ndarray:
        """Rows ``(t, x_P, y_P, ψ, θ, ω1, ω2, ω3, E)`` of the whole run.

        Each step's state is recorded (its lean read for ``stop_lean``) and all are read
        at once (:func:`_poses`: the rows of :meth:`steps`, bit for bit).

        Raises:
            SimulationDivergedError: the run diverged.
        """
        model, disc, data, n = self._start()
        b = model.body("disc").id
        xmat, xpos, qvel = data.xmat[b], data.xpos[b], data.qvel[:6]
        raw = np.empty((n + 1, 19))
        for k in range(n + 1):
            if k:
                mujoco.mj_step(model, data)
            raw[k, 0] = data.time
            raw[k, 1:10], raw[k, 10:13], raw[k, 13:] = xmat, xpos, qvel
            if k and self.stop_lean is not None:
                z = float(xmat[7])  # ê2_z: free_pose's lean
                if abs(math.asin(z if z != z else min(1.0, max(-1.0, z)))) > self.stop_lean:
                    raw = raw[:k + 1]
                    break
        check_healthy(model, data)
        return _poses(model, disc.radius, raw)
