"""Steady upright rolling of the Whipple bicycle, a sideways push, and its lean angle.

The states every Whipple measurement starts from:

* **steady rolling** at speed ``v``: upright, wheel rates ``v / r``, rolled for
  :data:`SETTLE_TIME` so that the soft contacts reach their equilibrium penetration; by
  the bicycle's mirror symmetry the lateral states stay zero (to round-off) and are set to
  exactly zero;
* **pushed**: steady rolling plus a lean rate ``φ̇₀`` about the ground line (through both
  contacts), as the benchmark's ``φ̇``: ``ω_x = φ̇₀`` at the rear frame and, at the rear
  axle (height ``z``), ``v_y = −φ̇₀ z``.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from wmr_mujoco.models.params import params_or_default
from wmr_mujoco.robots.whipple import builder
from wmr_mujoco.robots.whipple.params import WhippleParams

NAME = "whipple"
#: Rolling time before a measurement: many contact time constants, s.
SETTLE_TIME = 0.3
#: Tangent indices (nv = 9): free joint (v_x, v_y, v_z, ω_x, ω_y, ω_z), then
#: rear wheel, steer, front wheel.
Y, ROLL, YAW, STEER = 1, 3, 5, 7
NV = 9
#: Largest speed a measurement accepts, m/s.
MAX_SPEED = 30.0
#: Largest push, rad/s.
MAX_PUSH = 5.0


def compile_model(params: WhippleParams | None = None) -> mujoco.MjModel:
    """The bicycle on the project's floor: the checked-in scene, or built from ``params``."""
    from wmr_mujoco.models.loading import load
    from wmr_mujoco.robots.whipple import SPEC  # the entry imports this module

    return load(SPEC, params)


def check_speed(speed: float) -> None:
    """Raise ``ValueError`` unless ``0 <= speed <= MAX_SPEED`` m/s."""
    if not (isinstance(speed, (int, float)) and math.isfinite(speed)
            and 0.0 <= speed <= MAX_SPEED):
        raise ValueError(f"speed = {speed!r} m/s; valid range is [0, {MAX_SPEED:g}]")


def roll_steadily(model: mujoco.MjModel, data: mujoco.MjData,
                  params: WhippleParams | None, speed: float,
                  settle_time: float = SETTLE_TIME) -> None:
    """Put ``data`` in upright straight rolling at ``speed`` after the contacts settled.

    Raises:
        ValueError: ``speed`` outside ``[0, 30]`` m/s.
        RuntimeError: the run diverged while settling.
    """
    check_speed(speed)
    p = params_or_default(params, WhippleParams)
    mujoco.mj_resetData(model, data)
    data.qpos[:], data.qvel[:] = builder.rolling_state(p, speed)
    for _ in range(round(settle_time / model.opt.timestep)):
        mujoco.mj_step(model, data)
    if not np.all(np.isfinite(data.qpos)) or not np.all(np.isfinite(data.qvel)):
        raise RuntimeError(f"whipple model diverged while settling at {speed} m/s")
    # Remove the round-off in the lateral states (mirror symmetry keeps them zero).
    w, _, y, _ = data.qpos[3:7]
    pitch = 2.0 * math.atan2(y, w)
    data.qpos[3:7] = (math.cos(pitch / 2), 0.0, math.sin(pitch / 2), 0.0)
    data.qpos[1] = 0.0
    data.qpos[8] = 0.0
    data.qvel[[Y, ROLL, YAW, STEER]] = 0.0
    data.time = 0.0
    mujoco.mj_forward(model, data)


def steady_rolling(model: mujoco.MjModel, params: WhippleParams | None, speed: float
                   ) -> mujoco.MjData:
    """New data in steady rolling at ``speed`` (:func:`roll_steadily`)."""
    data = mujoco.MjData(model)
    roll_steadily(model, data, params, speed)
    return data


def push(model: mujoco.MjModel, data: mujoco.MjData, lean_rate: float) -> None:
    """Add a lean rate ``lean_rate`` (rad/s) about the ground line (module docstring).

    Raises:
        ValueError: ``lean_rate`` is 0, not finite, or larger than 5 rad/s in size.
    """
    if not (math.isfinite(lean_rate) and 0.0 < abs(lean_rate) <= MAX_PUSH):
        raise ValueError(f"lean_rate = {lean_rate!r} rad/s; valid range is "
                         f"(0, {MAX_PUSH:g}] in size")
    data.qvel[ROLL] += lean_rate
    data.qvel[Y] -= lean_rate * data.qpos[2]
    mujoco.mj_forward(model, data)


def pushed(model: mujoco.MjModel, data: mujoco.MjData, params: WhippleParams | None,
           speed: float, lean_rate: float) -> None:
    """Steady rolling at ``speed`` (:func:`roll_steadily`), then the push (:func:`push`).

    The command map's pushed start (:data:`~wmr_mujoco.validation.command.Pushed`).
    """
    roll_steadily(model, data, params, speed)
    push(model, data, lean_rate)


def readings(model: mujoco.MjModel, data: mujoco.MjData) -> dict[str, float]:
    """Lean (rad), lean rate (rad/s), steer (rad) and steer rate (rad/s) of ``data``.

    The lean rate is the rear frame's body ``ω_x``: with ``R = R_z(ψ) R_x(φ)`` (the rear
    frame level in pitch) the body angular velocity is ``(φ̇, ψ̇ sin φ, ψ̇ cos φ)``.
    """
    return {"lean": lean_angle(data.qpos[3:7]), "lean_rate": float(data.qvel[ROLL]),
            "steer": float(data.qpos[8]), "steer_rate": float(data.qvel[STEER])}


def lean_angle(quat: np.ndarray) -> float:
    """Lean φ (positive to the right) of the rear frame, ``φ = asin(R[2, 1])``.

    R is the body-to-world rotation; ``R[2, 1]`` is the height component of the body's
    y (left) axis, ``sin φ`` for any yaw and pitch in the benchmark's yaw-lean-pitch order.
    """
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, quat)
    return math.asin(max(-1.0, min(1.0, mat[7])))
