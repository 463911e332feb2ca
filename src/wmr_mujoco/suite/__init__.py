"""The wheeled robots' tasks in the style of ``dm_control.suite``.

::

    from wmr_mujoco import suite
    env = suite.load("diffdrive", "GoToGoal", task_kwargs={"random": 0})
    timestep = env.reset()
    while not timestep.last():
        timestep = env.step(env.action_spec().generate_value())

Each environment is a :class:`dm_control.rl.control.Environment` around the same robot and
task as the Gymnasium environment (:mod:`wmr_mujoco.envs`): one environment step is one
control period of the driven robot (:mod:`wmr_mujoco.drive`); the episode ends on success
or failure (discount 0) or at the task's time limit (discount 1).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from dm_control.rl import control

from wmr_mujoco.envs.profiles import drivable, profile
from wmr_mujoco.suite.task import DrivePhysics, SuiteTask

__all__ = ["ALL_TASKS", "DrivePhysics", "SuiteTask", "load"]

#: Keys of ``task_kwargs`` that are not task options.
SETUP_KEYS = ("random", "mode", "randomize", "control_period")


def all_tasks() -> tuple[tuple[str, str], ...]:
    """``(robot, task)`` of every drivable robot and task of its profile."""
    return tuple((robot, task) for robot in drivable() for task in profile(robot).tasks)


#: Every ``(robot, task)`` pair, like ``dm_control.suite.ALL_TASKS``.
ALL_TASKS: tuple[tuple[str, str], ...] = all_tasks()


def load(robot: str, task: str, task_kwargs: Mapping[str, Any] | None = None,
         environment_kwargs: Mapping[str, Any] | None = None) -> control.Environment:
    """The environment of ``robot`` on ``task``.

    Args:
        robot: a drivable robot (``ALL_TASKS``).
        task: one of its tasks.
        task_kwargs: ``random`` (seed or ``numpy.random.RandomState``), ``mode``
            (``"command"`` or ``"wheels"``), ``randomize`` (domain randomisation),
            ``control_period`` (s), and the task's options.
        environment_kwargs: passed to ``control.Environment`` (e.g. ``flat_observation``).

    Raises:
        ValueError: unknown robot, task or option (the valid names listed).
    """
    kwargs = dict(task_kwargs or {})
    setup = {k: kwargs.pop(k) for k in SETUP_KEYS if k in kwargs}
    env_kwargs = dict(environment_kwargs or {})
    if "time_limit" in env_kwargs or "control_timestep" in env_kwargs or \
            "n_sub_steps" in env_kwargs:
        raise ValueError("environment_kwargs: time_limit, control_timestep and n_sub_steps "
                         "come from the task (task_kwargs time_limit, control_period)")
    suite_task = SuiteTask(robot, task, options=kwargs, **setup)
    physics = DrivePhysics.from_episode(suite_task.episode)
    return control.Environment(physics, suite_task, time_limit=suite_task.episode.task.time_limit,
                               n_sub_steps=1, **env_kwargs)
