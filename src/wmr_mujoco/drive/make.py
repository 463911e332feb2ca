""":func:`make`: a registered robot, ready to be driven one control period at a time.

The stepping API's core takes a registry entry (:func:`wmr_mujoco.loop.build.build_robot`,
below the registry so that validation scenarios can close loops); this is its by-name
front door for users.
"""

from __future__ import annotations

from wmr_mujoco.loop.build import Backend, Mode, build_robot
from wmr_mujoco.loop.robot import Robot
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots import ROBOTS, get_spec

__all__ = ["Backend", "Mode", "drivable", "make"]


def drivable() -> list[str]:
    """Names of the registered robots that have a command map."""
    return [name for name, spec in ROBOTS.items() if spec.command is not None]


def make(robot: str, backend: str = "mujoco", control_period: float = 0.02,
         params: RobotParams | None = None, mode: str = "command") -> Robot:
    """A registered robot to drive with ``reset`` and ``step`` (the stepping API).

    Args:
        robot: a name from ``wmr list`` with a command map in its registry entry (every
            robot but ``disc_free``, which has no actuators).
        backend: ``"mujoco"`` (contact physics), ``"kinematic"`` (the robot's analytic
            kinematic model, the same natural commands) or ``"dynamic"`` (its Lagrange
            model under wheel torques, where it has one with a planar pose: omni3,
            mecanum4).
        control_period: seconds each :meth:`~Robot.step` holds its command; a multiple
            of the model's timestep.
        params: the robot's parameters (None: the checked-in model).
        mode: ``"command"`` (the robot's natural command, ``robot.command_space``),
            ``"wheels"`` (the actuators' own controls: wheel-rate and steering-rate servo
            targets, or the model's torques), ``"torque"`` (every actuator a torque, for
            models built by this package); the kinematic backend takes ``"command"``
            only, the dynamic backend wheel torques only.

    Raises:
        ValueError: unknown robot, backend or mode (the message lists the valid ones), a
            robot without actuators or without the backend's model (the message lists
            its backends), a bad control period, or parameters of the wrong type.
        TypeError: a control period that is not a number.
    """
    spec = get_spec(robot)
    if spec.command is None:
        raise ValueError(f"robot {robot!r} has no actuators and no command map: it cannot "
                         f"be driven; robots that can: {', '.join(drivable())}")
    return build_robot(spec, backend, control_period, params, mode)
