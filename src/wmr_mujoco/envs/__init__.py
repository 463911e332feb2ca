"""Gymnasium environments of the wheeled robots, registered as ``wmr/<Robot>-<Task>-v0``.

Importing this package registers one environment per drivable robot (a robot with
actuators, :mod:`wmr_mujoco.drive`) and task of its profile
(:mod:`wmr_mujoco.envs.profiles`)::

    import gymnasium as gym
    import wmr_mujoco.envs

    env = gym.make("wmr/DiffDrive-GoToGoal-v0")
    obs, info = env.reset(seed=0)

Needs the optional extra ``rl`` (``pip install wmr-mujoco[rl]``: gymnasium).
"""

from __future__ import annotations

import gymnasium as gym

from wmr_mujoco.envs.env import WmrEnv
from wmr_mujoco.envs.profiles import drivable, profile
from wmr_mujoco.envs.randomization import Bands

__all__ = ["ENV_IDS", "Bands", "WmrEnv", "env_id", "register_all"]


def env_id(robot: str, task: str) -> str:
    """``wmr/<stem>-<task>-v0`` of a robot and task."""
    return f"wmr/{profile(robot).stem}-{task}-v0"


def register_all() -> list[str]:
    """Register every (robot, task) pair not yet registered; return all their ids."""
    ids = []
    for robot in drivable():
        for task in profile(robot).tasks:
            name = env_id(robot, task)
            if name not in gym.registry:
                gym.register(name, entry_point="wmr_mujoco.envs.env:WmrEnv",
                             kwargs={"robot": robot, "task": task})
            ids.append(name)
    return ids


#: Every registered environment id.
ENV_IDS: tuple[str, ...] = tuple(register_all())
