"""Driving a robot one control period at a time: ``make``, ``reset``, ``step``.

::

    import wmr_mujoco as wmr
    robot = wmr.make("diffdrive", backend="mujoco", control_period=0.02)
    state = robot.reset(pose=(0.0, 0.0, 0.0), seed=None)
    for _ in range(100):
        state = robot.step((0.5, 0.3))          # (v m/s, ω rad/s), held for 20 ms

Backends: ``"mujoco"`` (contact physics, :mod:`.physics`) and ``"kinematic"`` (the robot's
analytic kinematic model under the same commands, :mod:`.kinematic`). Each robot's
command space and wheels come from its registry entry
(:class:`~wmr_mujoco.robots.command.CommandMap`), never from its name.
"""

from wmr_mujoco.drive.make import drivable, make
from wmr_mujoco.drive.robot import Robot
from wmr_mujoco.drive.state import CommandSpace, RobotState

__all__ = ["CommandSpace", "Robot", "RobotState", "drivable", "make"]
