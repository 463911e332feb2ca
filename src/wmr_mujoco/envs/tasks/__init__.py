"""The learning tasks, shared by :mod:`wmr_mujoco.envs` (Gymnasium) and :mod:`wmr_mujoco.suite`."""

from __future__ import annotations

from wmr_mujoco.envs.tasks.base import Field, Task, check_options
from wmr_mujoco.envs.tasks.follow import FollowPath
from wmr_mujoco.envs.tasks.goal import GoToGoal
from wmr_mujoco.envs.tasks.upright import StayUpright

__all__ = ["TASKS", "Field", "FollowPath", "GoToGoal", "StayUpright", "Task", "check_options",
           "task_class"]

#: Tasks by name.
TASKS: dict[str, type[Task]] = {t.name: t for t in (GoToGoal, FollowPath, StayUpright)}


def task_class(name: str) -> type[Task]:
    """A task by name.

    Raises:
        ValueError: unknown name; the message lists the valid ones.
    """
    try:
        return TASKS[name]
    except (KeyError, TypeError):
        raise ValueError(f"unknown task {name!r}; valid tasks: {', '.join(TASKS)}") from None
