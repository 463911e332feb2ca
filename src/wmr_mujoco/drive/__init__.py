"""Driving a robot one control period at a time: ``make``, ``reset``, ``step``.

::

    import wmr_mujoco as wmr
    robot = wmr.make("diffdrive", backend="mujoco", control_period=0.02)
    state = robot.reset(pose=(0.0, 0.0, 0.0), seed=None)
    for _ in range(100):
        state = robot.step((0.5, 0.3))          # (v m/s, ω rad/s), held for 20 ms

Backends: ``"mujoco"`` (contact physics, :mod:`wmr_mujoco.loop.physics`), ``"kinematic"``
(the robot's analytic kinematic model under the same commands,
:mod:`wmr_mujoco.loop.kinematic`) and ``"dynamic"`` (its Lagrange model under wheel
torques, :mod:`wmr_mujoco.loop.dynamic`). Each robot's command space and wheels come from
its registry entry (:class:`~wmr_mujoco.validation.command.CommandMap`), never from its
name. The steppable robots live in :mod:`wmr_mujoco.loop` (below the registry, so that
validation closes loops on them); this package adds the by-name :func:`make` and filming.
"""

from wmr_mujoco.drive.film import film
from wmr_mujoco.drive.make import drivable, make
from wmr_mujoco.loop.robot import Robot, set_filmer
from wmr_mujoco.loop.state import CommandSpace, RobotState

set_filmer(film)

__all__ = ["CommandSpace", "Robot", "RobotState", "drivable", "make"]
