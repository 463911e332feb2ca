"""The base of the tasks' step math over n worlds (:mod:`wmr_mujoco.envs.tasks.arrays`).

Each task's array class computes, for every world at once on arrays with a leading world
axis, the floats that its scalar task computes for one world, with the same floating-point
operations in the same order: numpy's elementwise ``+ − × ÷`` round as Python's floats do;
the functions of :mod:`math` (``sin``, ``cos``, ``exp``, ``hypot``, ``atan2``,
``remainder``) and Python's ``x ** 2`` (C ``pow``, which may differ from ``x · x`` in the
last bit) run on the worlds' Python floats through ``map`` (a C loop), chained so that one
``np.fromiter`` gathers every such value of a step.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Sequence

import numpy as np

from wmr_mujoco.envs.stepping import Snapshot
from wmr_mujoco.envs.tasks.base import EFFORT, Task
from wmr_mujoco.envs.worlds import States

#: ``(reward terms name -> (n,), success (n,), failure (n,))`` of one step.
Step = tuple[dict[str, np.ndarray], np.ndarray, np.ndarray]


def effort(actions: np.ndarray) -> np.ndarray:
    """``−EFFORT mean(a²)`` per world, summed channel by channel as the scalar code does."""
    sq = actions * actions
    total = sq[:, 0]
    for j in range(1, actions.shape[1]):
        total = total + sq[:, j]
    return -EFFORT * total / actions.shape[1]


def bonus(flag: np.ndarray, value: float) -> np.ndarray:
    """``value`` where ``flag``, else 0."""
    return np.where(flag, value, 0.0)


class TaskArrays(ABC):
    """One task's step over n worlds (module docstring).

    Args:
        tasks: the worlds' scalar tasks (one class, one set of options).
    """

    def __init__(self, tasks: Sequence[Task]) -> None:
        self.tasks = list(tasks)
        self.n = len(self.tasks)
        first = self.tasks[0]
        self.scale = first.scale
        self.options = first.options
        self.time_limit = first.time_limit

    @abstractmethod
    def load(self, i: int, state: Snapshot) -> None:
        """Take world ``i``'s new episode from its task, and its first state."""

    @abstractmethod
    def step(self, s: States, actions: np.ndarray, dt: float, out: np.ndarray) -> Step:
        """The reward terms and outcome of every world's step to ``s``.

        The task's observation block is written into the first columns of ``out`` (n, …).
        """

    def succeeded_at_time_limit(self, s: States) -> np.ndarray:
        """Per world: whether running to the time limit counts as a success (default no)."""
        return np.zeros(self.n, np.bool_)
