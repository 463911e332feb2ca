"""The vector environment's step of a few worlds: each world through its single environment.

Below :data:`~wmr_mujoco.envs.vector.BATCHED_FROM` worlds the native vector environment
(:mod:`wmr_mujoco.envs.vector`) steps each world as its single environment does
(:meth:`~wmr_mujoco.envs.episode.Episode.push` then
:meth:`~wmr_mujoco.envs.episode.Episode.pull`, the very calls of ``env.step``): every world's
physics first, then every world's reading and task (so that their Python code runs warm
for all worlds but the first). The batch is assembled from those results: the observations
stacked, the rewards, flags and info values gathered into arrays with a world axis. The
batched path (:mod:`wmr_mujoco.envs.batched`) computes the reading and the task once on
arrays, which pays only from a dozen worlds on (numpy's per-call cost against the scalar
code's per-world cost). Both give the single environments' results bit for bit.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from wmr_mujoco.envs.episode import Episode

#: ``(observations (n, size) float32, rewards (n,), terminated (n,), truncated (n,),
#: (reward terms name -> (n,), success (n,), failure (n,), time (n,)))`` of one step; the
#: rows of worlds that did not step are undefined.
Result = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray,
               tuple[dict[str, np.ndarray], np.ndarray, np.ndarray, np.ndarray]]


class Serial:
    """Steps the worlds of ``episodes`` one by one (module docstring).

    Args:
        episodes: one :class:`Episode` per world.
    """

    def __init__(self, episodes: Sequence[Episode]) -> None:
        self.episodes = list(episodes)
        self.n = len(self.episodes)
        self._push = [e.push for e in self.episodes]
        self._pull = [e.pull for e in self.episodes]
        self._size = self.episodes[0].size

    def load(self, i: int) -> None:
        """World ``i`` was reset (its episode keeps its own state: nothing to take)."""

    def step(self, actions: np.ndarray, active: np.ndarray | None = None) -> Result:
        """Every world's (or ``active``'s) step under ``actions`` (n, m), checked.

        Raises:
            SimulationDivergedError: a world's physics diverged.
        """
        rows = actions.tolist()
        if active is None:
            for push, a in zip(self._push, rows, strict=True):
                push(a)
            out = [pull() for pull in self._pull]
            return _gather(out)
        worlds = np.flatnonzero(active).tolist()
        if not worlds:  # every world was reset: no step (the caller fills every row)
            return _spread(None, worlds, self.n, self._size)
        for i in worlds:
            self._push[i](rows[i])
        part = _gather([self._pull[i]() for i in worlds])
        return _spread(part, worlds, self.n, self._size)


def _gather(out: list[tuple]) -> Result:
    """The worlds' ``(obs, reward, terminated, truncated, info)`` as arrays over the worlds."""
    obs, reward, term, trunc, infos = zip(*out, strict=True)
    terms = [info["reward_terms"] for info in infos]
    flags = ({k: np.array([t[k] for t in terms]) for k in terms[0]},
             np.array([info["is_success"] for info in infos]),
             np.array([info["failed"] for info in infos]),
             np.array([info["time"] for info in infos]))
    return np.array(obs), np.array(reward), np.array(term), np.array(trunc), flags


def _spread(part: Result | None, worlds: list[int], n: int, size: int) -> Result:
    """``part`` (the rows of ``worlds``) placed into arrays of ``n`` rows (others zero).

    ``part`` None: no world stepped (every array zero, no reward terms).
    """
    def put(values: np.ndarray, shape: tuple[int, ...] = ()) -> np.ndarray:
        full = np.zeros((n, *shape), values.dtype)
        full[worlds] = values
        return full

    if part is None:
        no = np.zeros(n, np.bool_)
        return np.zeros((n, size), np.float32), np.zeros(n), no, no.copy(), ({}, no.copy(),
                                                                         no.copy(), np.zeros(n))
    obs, reward, term, trunc, (terms, success, failure, time) = part
    return (put(obs, (size,)), put(reward), put(term), put(trunc),
            ({k: put(v) for k, v in terms.items()}, put(success), put(failure), put(time)))
