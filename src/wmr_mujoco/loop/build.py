""":func:`build_robot`: a robot's registry entry, ready to be driven one period at a time.

This is the stepping API's core: it receives a :class:`~wmr_mujoco.validation.spec.RobotSpec`
(never a name to look up), so that validation scenarios can close loops on it;
:func:`wmr_mujoco.make` (application layer) looks the name up and calls it.

Backends (:class:`Backend`):

* ``"mujoco"``: contact physics (:class:`~wmr_mujoco.loop.physics.MujocoRobot`);
* ``"kinematic"``: the robot's analytic kinematic model under the same natural commands
  (:class:`~wmr_mujoco.loop.kinematic.KinematicRobot`), where its command map has one;
* ``"dynamic"``: the robot's Lagrange model under wheel torques
  (:class:`~wmr_mujoco.loop.dynamic.DynamicRobot`), where the robot's dynamic adapter
  has a planar pose in its state (:func:`~wmr_mujoco.loop.dynamic.dynamic_adapter`).
"""

from __future__ import annotations

import enum

import mujoco
import numpy as np

from wmr_mujoco.choices import parse_choice
from wmr_mujoco.loop.physics import MujocoRobot
from wmr_mujoco.loop.robot import Robot
from wmr_mujoco.loop.state import CommandSpace
from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.builders.common import NUSER_ACTUATOR
from wmr_mujoco.models.loading import load
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.validation.scenarios import ScenarioKind
from wmr_mujoco.validation.spec import RobotSpec


class Backend(str, enum.Enum):
    """What moves the robot."""

    MUJOCO = "mujoco"
    KINEMATIC = "kinematic"
    DYNAMIC = "dynamic"


class Mode(str, enum.Enum):
    """What a command is."""

    COMMAND = "command"
    WHEELS = "wheels"
    TORQUE = "torque"


def backends(spec: RobotSpec, params: RobotParams | None = None) -> list[str]:
    """The backends ``spec`` can be driven on (empty: it has no command map)."""
    from wmr_mujoco.loop.dynamic import dynamic_adapter

    if spec.command is None:
        return []
    out = [Backend.MUJOCO.value]
    if spec.command.analytic(params) is not None:
        out.append(Backend.KINEMATIC.value)
    if ScenarioKind.DYNAMIC in spec.adapters:
        try:
            dynamic_adapter(spec, load(spec, params), params)
            out.append(Backend.DYNAMIC.value)
        except ValueError:
            pass
    return out


def actuator_space(model: mujoco.MjModel, torque: bool) -> CommandSpace:
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


def build_robot(spec: RobotSpec, backend: str = "mujoco", control_period: float = 0.02,
                params: RobotParams | None = None, mode: str = "command",
                model: mujoco.MjModel | None = None) -> Robot:
    """The robot of ``spec`` to drive with ``reset`` and ``step`` (see :func:`wmr_mujoco.make`).

    Args:
        spec: the robot's registry entry, with a command map.
        backend: ``"mujoco"``, ``"kinematic"`` or ``"dynamic"`` (module docstring).
        control_period: seconds each step holds its command; a multiple of the timestep.
        params: the robot's parameters (None: the checked-in model).
        mode: ``"command"``, ``"wheels"`` or ``"torque"`` (the kinematic backend takes
            ``"command"`` only, the dynamic backend ``"torque"`` only).
        model: the robot's compiled scene to use (None: loaded; modified in place).

    Raises:
        ValueError: unknown backend or mode (the message lists the valid ones), a robot
            without actuators or without the backend's model (the message lists the
            backends it has), a bad control period, or parameters of the wrong type.
        TypeError: a control period that is not a number.
    """
    backend_ = parse_choice(Backend, backend, "backend")
    mode_ = parse_choice(Mode, mode, "mode")
    cmap = spec.command
    if cmap is None:
        raise ValueError(f"robot {spec.name!r} has no actuators and no command map: it "
                         "cannot be driven")
    if backend_ is Backend.DYNAMIC:
        from wmr_mujoco.loop.dynamic import DynamicRobot, dynamic_adapter

        if mode_ is Mode.COMMAND and mode == "command":
            mode_ = Mode.TORQUE  # the dynamic model's natural input is the wheel torques
        if mode_ is not Mode.TORQUE:
            raise ValueError(f"mode = {mode!r}: the dynamic backend takes mode='torque' only")
        model = load(spec, params) if model is None else model
        try:
            adapter = dynamic_adapter(spec, model, params)
        except ValueError as err:
            raise ValueError(f"{err}: no dynamic backend; its backends: "
                             f"{', '.join(backends(spec, params))}") from None
        return _finish(DynamicRobot(spec, model, adapter, control_period), params)
    adapter = cmap.analytic(params) if backend_ is Backend.KINEMATIC or \
        mode_ is Mode.COMMAND else None
    if backend_ is Backend.KINEMATIC:
        if adapter is None:
            raise ValueError(f"robot {spec.name!r} has no kinematic model; its backends: "
                             f"{', '.join(backends(spec, params))}")
        if mode_ is not Mode.COMMAND:
            raise ValueError(f"mode = {mode!r}: the kinematic backend takes "
                             f"mode='command' only")
    model = load(spec, params) if model is None else model
    if mode_ is Mode.TORQUE and model.nuser_actuator < NUSER_ACTUATOR:
        raise ValueError(f"mode = 'torque': robot {spec.name!r} keeps its own actuators "
                         "(no rate/torque switching); use mode='command' or 'wheels'")
    if backend_ is Backend.KINEMATIC:
        from wmr_mujoco.loop.kinematic import KinematicRobot

        low, high = cmap.limits(model, adapter)
        space = CommandSpace(cmap.names, cmap.units, low, high)
        robot = KinematicRobot(spec, model, adapter, control_period, space)
    elif mode_ is Mode.COMMAND:
        low, high = cmap.limits(model, adapter)
        space = CommandSpace(cmap.names, cmap.units, low, high)
        actuation = getattr(adapter, "mode", None)
        robot = MujocoRobot(spec, model, "command", control_period, space,
                            cmap.bind(model, adapter), actuation)
    else:
        torque = mode_ is Mode.TORQUE
        actuation = (ActuationMode.TORQUE if torque else ActuationMode.RATE) \
            if model.nuser_actuator >= NUSER_ACTUATOR else None
        robot = MujocoRobot(spec, model, mode_.value, control_period,
                            actuator_space(model, torque), None, actuation)
    return _finish(robot, params)


def _finish(robot: Robot, params: RobotParams | None) -> Robot:
    assert np.all(robot.command_space.low <= robot.command_space.high)
    robot.params = params
    return robot
