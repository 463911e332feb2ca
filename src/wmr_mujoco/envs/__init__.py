"""Gymnasium environments of the wheeled robots, registered as ``wmr/<Robot>-<Task>-v0``.

Importing this package registers one environment per drivable robot (a robot with
actuators, :mod:`wmr_mujoco.drive`) and task that its registry entry offers
(``RobotSpec.learning``, read by :mod:`wmr_mujoco.envs.profiles`)::

    import gymnasium as gym
    import wmr_mujoco.envs

    env = gym.make("wmr/DiffDrive-GoToGoal-v0")
    obs, info = env.reset(seed=0)

    envs = gym.make_vec("wmr/DiffDrive-GoToGoal-v0", num_envs=8)  # n worlds, one loop

Needs the optional extra ``rl`` (``pip install wmr-mujoco[rl]``: gymnasium). Without it the
tasks and the dm_control suite (:mod:`wmr_mujoco.suite`) still work; ``WmrEnv`` then
raises ImportError naming the extra.
"""

from __future__ import annotations

from typing import Any

from wmr_mujoco.envs.profiles import drivable, profile
from wmr_mujoco.envs.randomization import Bands

try:
    import gymnasium as gym
except ModuleNotFoundError:  # the optional extra is not installed
    gym = None

__all__ = ["ENV_IDS", "Bands", "WmrEnv", "env_id", "profile", "register_all"]

MISSING = "Gymnasium is not installed; install the extra: pip install 'wmr-mujoco[rl]'"


def env_id(robot: str, task: str) -> str:
    """``wmr/<stem>-<task>-v0`` of a robot and task."""
    return f"wmr/{profile(robot).stem}-{task}-v0"


def register_all() -> list[str]:
    """Register every (robot, task) pair not yet registered; return all their ids.

    Raises:
        ImportError: Gymnasium is not installed.
    """
    if gym is None:
        raise ImportError(MISSING)
    ids = []
    for robot in drivable():
        for task in profile(robot).tasks:
            name = env_id(robot, task)
            if name not in gym.registry:
                # Without Gymnasium's passive checker and order-enforcing wrappers: the
                # environment checks every action itself and refuses step() before
                # reset(), and each wrapper costs a call per step (check_env passes).
                gym.register(name, entry_point="wmr_mujoco.envs.env:WmrEnv",
                             vector_entry_point="wmr_mujoco.envs.vector:WmrVectorEnv",
                             kwargs={"robot": robot, "task": task},
                             disable_env_checker=True, order_enforce=False)
            ids.append(name)
    return ids


#: Every registered environment id (empty without Gymnasium).
ENV_IDS: tuple[str, ...] = tuple(register_all()) if gym is not None else ()


def __getattr__(name: str) -> Any:
    if name == "WmrEnv":
        if gym is None:
            raise ImportError(MISSING)
        from wmr_mujoco.envs.env import WmrEnv

        return WmrEnv
    raise AttributeError(f"module 'wmr_mujoco.envs' has no attribute {name!r}")
