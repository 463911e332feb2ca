"""The vector environment's step of many worlds: the reading and the task once, on arrays.

From :data:`~wmr_mujoco.envs.vector.BATCHED_FROM` worlds on, the native vector environment
(:mod:`wmr_mujoco.envs.vector`) steps every world's physics
(:class:`~wmr_mujoco.envs.worlds.Worlds`: its own command map and ``mj_step`` calls, the
only per-world Python), reads every world into arrays with a leading world axis, computes
the task's observation block, reward terms and outcome once for all worlds
(:mod:`wmr_mujoco.envs.tasks.arrays`), and assembles the observations, rewards and flags
as arrays. The arithmetic is the single environment's floating-point operations in the same
order, so world ``i`` gives its single environment's results bit for bit
(``tests/envs/test_vector.py``). The worlds' single environments are not stepped: after a
step, ``envs[i].episode.state`` stays at the world's last reset (its robot's ``data`` is
current).

Per step: ``obs = (task block, u, v, r, wheel rates, a)`` in float32; ``reward = Σ terms``
(as Python's ``sum`` adds them: :func:`total`); ``truncated = t ≥ T − 10⁻⁹ ∧ ¬(success ∨
failure)`` (then ``success`` is the task's verdict at the time limit); ``terminated =
(success ∨ failure) ∧ ¬truncated``.
"""

from __future__ import annotations

import sys
from collections.abc import Mapping, Sequence

import numpy as np

from wmr_mujoco.envs.episode import Episode
from wmr_mujoco.envs.serial import Result
from wmr_mujoco.envs.tasks.arrays import ARRAYS
from wmr_mujoco.envs.worlds import Worlds

#: Whether Python's ``sum`` of floats is compensated (Neumaier's, from Python 3.12), so that
#: the single environment's ``sum(terms.values())`` is not a plain sequence of additions.
COMPENSATED = sys.version_info >= (3, 12)


def total(terms: Mapping[str, np.ndarray], compensated: bool = COMPENSATED) -> np.ndarray:
    """Per world ``sum(terms.values())`` as Python computes it: the reward.

    Plain additions in the terms' order from 0 where ``sum`` adds plainly; else ``sum``
    itself over each world's floats.
    """
    if compensated:
        columns = [v.tolist() for v in terms.values()]
        return np.fromiter(map(sum, zip(*columns, strict=True)), float, len(columns[0]))
    reward = 0.0
    for v in terms.values():
        reward = reward + v
    return reward


class Batched:
    """The batched step of the worlds of ``episodes`` (module docstring).

    Args:
        episodes: one :class:`Episode` per world, all of one robot and task.
    """

    def __init__(self, episodes: Sequence[Episode]) -> None:
        self.episodes = list(episodes)
        first = self.episodes[0]
        n = len(self.episodes)
        self.worlds = Worlds(self.episodes)
        self.tasks = ARRAYS[first.task.name](tuple(e.task for e in self.episodes))
        self.dt = first.dt
        #: The step's observations in float64 (the task's block, twist, wheel rates,
        #: action) and where the robot's blocks start.
        self._full = np.zeros((n, first.size))
        t0 = first.task.size
        self._cols = (t0, t0 + 3, t0 + 3 + len(first.robot.wheel_names))
        self._limit = self.tasks.time_limit - 1e-9

    def load(self, i: int) -> None:
        """Take world ``i``'s reset into the arrays (its physics' origin, its episode)."""
        self.worlds.load(i)
        self.tasks.load(i, self.episodes[i].state)

    def step(self, actions: np.ndarray, active: np.ndarray | None = None) -> Result:
        """Every world's (or ``active``'s) step under ``actions`` (n, m), checked.

        The rows of the worlds that did not step are undefined (the caller reloads them,
        :meth:`load`).

        Raises:
            SimulationDivergedError: a world's physics diverged.
        """
        self.worlds.push(actions, active)
        s = self.worlds.read()
        full, (t0, t1, t2) = self._full, self._cols
        terms, success, failure = self.tasks.step(s, actions, self.dt, full)
        full[:, t0:t1] = s.uvr
        full[:, t1:t2] = s.wheel_rates
        full[:, t2:] = actions
        reward = total(terms)
        done = success | failure
        truncated = np.greater(s.time >= self._limit, done)  # t ≥ T ∧ ¬done
        if truncated.tobytes().count(1):
            success = np.where(truncated, self.tasks.succeeded_at_time_limit(s), success)
            terminated = np.greater(done, truncated)
        else:
            terminated = done
        return (full.astype(np.float32), reward, terminated, truncated,
                (terms, success, failure, s.time))
