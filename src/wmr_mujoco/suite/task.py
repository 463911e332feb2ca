"""A :class:`dm_control.rl.control.Task` around :class:`wmr_mujoco.envs.episode.Episode`.

:class:`DrivePhysics` is a ``dm_control.mujoco.Physics`` on the driven robot's own
``MjData`` (shared, not copied), whose :meth:`~DrivePhysics.step` advances one control
period through the stepping API (:mod:`wmr_mujoco.drive`) and whose
:meth:`~DrivePhysics.timestep` is that period; the environment is built with
``n_sub_steps=1``, so ``env.control_timestep()`` is the control period.
"""

from __future__ import annotations

import collections
import re
from collections.abc import Mapping
from typing import Any

import numpy as np
from dm_control import mujoco
from dm_control.mujoco.wrapper import core
from dm_control.suite import base
from dm_env import specs

from wmr_mujoco.envs.episode import Episode
from wmr_mujoco.envs.randomization import Bands


class DrivePhysics(mujoco.Physics):
    """Physics stepped one control period at a time by an :class:`Episode` (docstring)."""

    episode: Episode
    _action: np.ndarray | None = None
    last: tuple[np.ndarray, float, bool, bool, dict] | None = None

    @classmethod
    def from_episode(cls, episode: Episode) -> DrivePhysics:
        """A physics sharing ``episode.robot.data``."""
        physics = cls(core.MjData(episode.robot.data))
        physics.episode = episode
        return physics

    def set_action(self, action: np.ndarray) -> None:
        """The normalised action held over the next :meth:`step`."""
        self._action = action

    def step(self, nstep: int = 1) -> None:
        """``nstep`` control periods of the episode under the last action."""
        if self._action is None:
            raise RuntimeError("no action: call the environment's step(action)")
        for _ in range(nstep):
            self.last = self.episode.step(self._action)

    def timestep(self) -> float:
        """One control period, s (what :meth:`step` advances)."""
        return self.episode.dt


def _key(name: str) -> str:
    """Observation key of a field name: its first word (``goal_xy``, ``twist``)."""
    return re.split(r"[ (]", name, maxsplit=1)[0]


class SuiteTask(base.Task):
    """One robot and task (see :mod:`wmr_mujoco.suite`).

    Args:
        robot: a drivable robot.
        task: one of its tasks.
        options: the task's options.
        random: seed or ``numpy.random.RandomState`` (None: fresh entropy).
        mode: ``"command"`` or ``"wheels"``.
        randomize: domain randomisation (False, True or a Bands).
        control_period: s per step (None: the robot's profile).
    """

    def __init__(self, robot: str, task: str, options: Mapping[str, float] | None = None,
                 random: int | np.random.RandomState | None = None, mode: str = "command",
                 randomize: bool | Bands = False, control_period: float | None = None) -> None:
        self.episode = Episode(robot, task, mode, randomize, options, control_period)
        super().__init__(random=random)

    def initialize_episode(self, physics: DrivePhysics) -> None:
        """Draw and start a new episode (seeded by the task's random state)."""
        physics.last = None
        self.episode.reset(np.random.default_rng(self.random.randint(2**31)))

    def before_step(self, action: np.ndarray, physics: DrivePhysics) -> None:
        """Hand the (checked) action to the physics."""
        physics.set_action(np.asarray(action))

    def get_observation(self, physics: DrivePhysics) -> collections.OrderedDict:
        """The observation's blocks by name (float64; see :mod:`wmr_mujoco.envs.episode`)."""
        flat = self.episode.observe().astype(np.float64)
        out, k = collections.OrderedDict(), 0
        for f in self.episode.fields:
            out[_key(f.name)] = flat[k:k + f.size]
            k += f.size
        return out

    def observation_spec(self, physics: DrivePhysics) -> collections.OrderedDict:
        """One float64 array per block."""
        return collections.OrderedDict(
            (_key(f.name), specs.Array((f.size,), np.float64, name=_key(f.name)))
            for f in self.episode.fields)

    def action_spec(self, physics: DrivePhysics) -> specs.BoundedArray:
        """The normalised command, ``[-1, 1]`` per channel."""
        n = self.episode.n_action
        return specs.BoundedArray((n,), np.float64, -np.ones(n), np.ones(n), name="action")

    def get_reward(self, physics: DrivePhysics) -> float:
        """The last step's reward (the sum of its terms; 0 before any step)."""
        return 0.0 if physics.last is None else physics.last[1]

    def get_termination(self, physics: DrivePhysics) -> float | None:
        """Discount 0 on success or failure, else None (the time limit truncates)."""
        if physics.last is not None and physics.last[2]:
            return 0.0
        return None

    def reward_terms(self, physics: DrivePhysics) -> dict[str, Any]:
        """The last step's info: reward terms, success, failure, time."""
        return {} if physics.last is None else physics.last[4]
