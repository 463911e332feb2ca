"""Switching a compiled model between rate (servo) control and torque control.

Every actuator the builders make carries ``user = [kind, kp, kv, rate_limit]``
(see :mod:`wmr_mujoco.models.builders.common`); its ``forcerange`` is the torque limit.

Rate mode (the models' default):
    * wheel:    ``τ = kv (u − θ̇)``, ``u`` the wheel rate (MuJoCo ``velocity``).
    * steering: ``ẋ_act = u``, ``τ = kp (x_act − φ) − kv φ̇``, ``u`` the steering
      rate ω (MuJoCo ``intvelocity``).
Torque mode:
    * every actuator: ``τ = u``, ``u`` in the torque range.
In both modes ``|τ|`` is clamped to the actuator's ``forcerange``.
"""

from __future__ import annotations

import enum

import mujoco
import numpy as np

from wmr_mujoco.choices import parse_choice
from wmr_mujoco.models.builders.common import KIND_STEER, KIND_WHEEL, NUSER_ACTUATOR


class ActuationMode(str, enum.Enum):
    """How actuator controls are interpreted."""

    RATE = "rate"
    TORQUE = "torque"


def _parse_mode(mode: ActuationMode | str) -> ActuationMode:
    return parse_choice(ActuationMode, mode, "actuation mode")


def _check_model(model: mujoco.MjModel) -> None:
    if model.nu == 0:
        raise ValueError(f"model {model.names[:20]!r}... has no actuators to switch")
    if model.nuser_actuator < NUSER_ACTUATOR:
        raise ValueError(
            f"model has nuser_actuator={model.nuser_actuator}; actuation switching needs "
            f"the {NUSER_ACTUATOR} user values written by the wmr_mujoco builders"
        )


def set_actuation_mode(model: mujoco.MjModel, mode: ActuationMode | str) -> None:
    """Switch every actuator of ``model`` to rate or torque control, in place.

    Call ``mujoco.mj_resetData`` (or keep ``data.act`` meaningful) afterwards if the
    model was already stepping: in rate mode the steering servo's state ``act`` is
    its target angle.

    Args:
        model: a model compiled from a wmr_mujoco robot.
        mode: ``"rate"`` or ``"torque"``.

    Raises:
        ValueError: unknown mode, or a model without the builders' actuator data.

    """
    mode = _parse_mode(mode)
    _check_model(model)
    for i in range(model.nu):
        kind, kp, kv, rate_limit = model.actuator_user[i, :NUSER_ACTUATOR]
        model.actuator_gaintype[i] = mujoco.mjtGain.mjGAIN_FIXED
        model.actuator_biastype[i] = mujoco.mjtBias.mjBIAS_AFFINE
        model.actuator_gainprm[i, :] = 0.0
        model.actuator_biasprm[i, :] = 0.0
        model.actuator_ctrllimited[i] = 1
        if mode is ActuationMode.TORQUE:
            model.actuator_dyntype[i] = mujoco.mjtDyn.mjDYN_NONE
            model.actuator_gainprm[i, 0] = 1.0
            model.actuator_ctrlrange[i] = model.actuator_forcerange[i]
        elif int(kind) == KIND_WHEEL:
            model.actuator_dyntype[i] = mujoco.mjtDyn.mjDYN_NONE
            model.actuator_gainprm[i, 0] = kv
            model.actuator_biasprm[i, 2] = -kv
            model.actuator_ctrlrange[i] = (-rate_limit, rate_limit)
        elif int(kind) == KIND_STEER:
            model.actuator_dyntype[i] = mujoco.mjtDyn.mjDYN_INTEGRATOR
            model.actuator_gainprm[i, 0] = kp
            model.actuator_biasprm[i, 1] = -kp
            model.actuator_biasprm[i, 2] = -kv
            model.actuator_ctrlrange[i] = (-rate_limit, rate_limit)
        else:
            raise ValueError(f"actuator {i} has unknown kind {kind!r} in its user data")


def actuation_mode(model: mujoco.MjModel) -> ActuationMode:
    """Return the mode the model's actuators are in (from their gains)."""
    _check_model(model)
    torque = np.all(model.actuator_biasprm[:, :3] == 0.0) and np.all(
        model.actuator_gainprm[:, 0] == 1.0)
    return ActuationMode.TORQUE if torque else ActuationMode.RATE
