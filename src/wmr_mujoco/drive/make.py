""":func:`make`: a registered robot, ready to be driven one control period at a time."""

from __future__ import annotations

import enum

import mujoco
import numpy as np

import wmr_mujoco
from wmr_mujoco.choices import parse_choice
from wmr_mujoco.drive.physics import MujocoRobot
from wmr_mujoco.drive.robot import Robot
from wmr_mujoco.drive.state import CommandSpace
from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.builders.common import NUSER_ACTUATOR
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots import ROBOTS, get_spec


class Backend(str, enum.Enum):
    """What moves the robot."""

    MUJOCO = "mujoco"
    KINEMATIC = "kinematic"


class Mode(str, enum.Enum):
    """What a command is."""

    COMMAND = "command"
    WHEELS = "wheels"
    TORQUE = "torque"


def drivable() -> list[str]:
    """Names of the registered robots that have a command map."""
    return [name for name, spec in ROBOTS.items() if spec.command is not None]


def _actuator_space(model: mujoco.MjModel, torque: bool) -> CommandSpace:
    """One channel per actuator: its ctrl range (rate mode) or torque range."""
    names = tuple(model.actuator(i).name for i in range(model.nu))
    if torque:
        ranges = model.actuator_forcerange.copy()
        units = ("N·m",) * model.nu
    else:
        ranges = model.actuator_ctrlrange.copy()
        servo = model.actuator_biastype != mujoco.mjtBias.mjBIAS_NONE
        units = tuple("rad/s" if s else "N·m" for s in servo)
    return CommandSpace(names, units, ranges[:, 0].copy(), ranges[:, 1].copy())


def make(robot: str, backend: str = "mujoco", control_period: float = 0.02,
         params: RobotParams | None = None, mode: str = "command") -> Robot:
    """A registered robot to drive with ``reset`` and ``step`` (the stepping API).

    Args:
        robot: a name from ``wmr list`` with a command map in its registry entry (every
            robot but ``disc_free``, which has no actuators).
        backend: ``"mujoco"`` (contact physics) or ``"kinematic"`` (the robot's analytic
            kinematic model, the same natural commands).
        control_period: seconds each :meth:`~Robot.step` holds its command; a multiple
            of the model's timestep.
        params: the robot's parameters (None: the checked-in model).
        mode: ``"command"`` (the robot's natural command, ``robot.command_space``),
            ``"wheels"`` (the actuators' own controls: wheel-rate and steering-rate servo
            targets, or the model's torques), ``"torque"`` (every actuator a torque, for
            models built by this package); the analytic backends take ``"command"`` only.

    Raises:
        ValueError: unknown robot, backend or mode (the message lists the valid ones), a
            robot without actuators or without the backend's model, a bad control period,
            or parameters of the wrong type.
        TypeError: a control period that is not a number.
    """
    spec = get_spec(robot)
    backend_ = parse_choice(Backend, backend, "backend")
    mode_ = parse_choice(Mode, mode, "mode")
    cmap = spec.command
    if cmap is None:
        raise ValueError(f"robot {robot!r} has no actuators and no command map: it cannot "
                         f"be driven; robots that can: {', '.join(drivable())}")
    adapter = cmap.analytic(params) if backend_ is Backend.KINEMATIC or \
        mode_ is Mode.COMMAND else None
    if backend_ is Backend.KINEMATIC:
        if adapter is None:
            raise ValueError(f"robot {robot!r} has no kinematic model; its backends: "
                             f"{Backend.MUJOCO.value}")
        if mode_ is not Mode.COMMAND:
            raise ValueError(f"mode = {mode!r}: the kinematic backend takes "
                             f"mode='command' only")
    model = wmr_mujoco.load(robot, params)
    if mode_ is Mode.TORQUE and model.nuser_actuator < NUSER_ACTUATOR:
        raise ValueError(f"mode = 'torque': robot {robot!r} keeps its own actuators "
                         "(no rate/torque switching); use mode='command' or 'wheels'")
    if backend_ is Backend.KINEMATIC:
        from wmr_mujoco.drive.kinematic import KinematicRobot

        low, high = cmap.limits(model, adapter)
        space = CommandSpace(cmap.names, cmap.units, low, high)
        robot_ = KinematicRobot(spec, model, adapter, control_period, space)
    elif mode_ is Mode.COMMAND:
        low, high = cmap.limits(model, adapter)
        space = CommandSpace(cmap.names, cmap.units, low, high)
        actuation = getattr(adapter, "mode", None)
        robot_ = MujocoRobot(spec, model, "command", control_period, space,
                             cmap.bind(model, adapter), actuation)
    else:
        torque = mode_ is Mode.TORQUE
        actuation = (ActuationMode.TORQUE if torque else ActuationMode.RATE) \
            if model.nuser_actuator >= NUSER_ACTUATOR else None
        robot_ = MujocoRobot(spec, model, mode_.value, control_period,
                             _actuator_space(model, torque), None, actuation)
    assert np.all(robot_.command_space.low <= robot_.command_space.high)
    robot_.params = params
    return robot_
