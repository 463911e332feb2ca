"""The tasks' step math over n worlds at once, on arrays with a leading world axis.

The native vector environment's batched path (:mod:`wmr_mujoco.envs.batched`) computes
each step's task block of the observation, reward terms and outcome once for every world
with these classes; the single environment keeps its scalar code
(:mod:`~wmr_mujoco.envs.tasks.goal`, :mod:`~wmr_mujoco.envs.tasks.follow`,
:mod:`~wmr_mujoco.envs.tasks.upright`, whose docstrings give the equations). Each class
here is the same equations, in the same order of floating-point operations
(:mod:`~wmr_mujoco.envs.tasks.array_base`), so every result equals the scalar task's bit
for bit (``tests/envs/test_arrays.py``, ``tests/envs/test_vector.py``).

A world's episode (goal, path, target speed) is drawn by its scalar task at the world's
reset; :meth:`TaskArrays.load` then copies it, and the first state's measurement, into
row ``i``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from itertools import chain, repeat
from operator import neg, sub, truediv

import numpy as np

from wmr_mujoco.envs.stepping import Snapshot
from wmr_mujoco.envs.tasks.array_base import Step, TaskArrays, bonus, effort
from wmr_mujoco.envs.tasks.base import Task
from wmr_mujoco.envs.tasks.goal import BONUS
from wmr_mujoco.envs.tasks.path_arrays import PathArrays
from wmr_mujoco.envs.worlds import States, each

__all__ = ["ARRAYS", "GoalArrays", "PathArrays", "Step", "TaskArrays", "UprightArrays",
           "bonus", "effort"]

#: ``½ / π``, the heading potential's weight (evaluated as the scalar code does).
HALF_OVER_PI = 0.5 / math.pi


class GoalArrays(TaskArrays):
    """:class:`~wmr_mujoco.envs.tasks.goal.GoToGoal` over n worlds.

    Keeps per world the goal ``(x_g, y_g, ψ_g)`` (and ``ψ_g`` as floats), the last distance
    ``d₋`` and the last heading potential term ``|e_ψ| e^{−d/L}``.
    """

    def __init__(self, tasks: Sequence[Task]) -> None:
        super().__init__(tasks)
        self.goal = np.zeros((self.n, 3))
        self._goal_heading = [0.0] * self.n
        self.d = np.zeros(self.n)
        self.phi = np.zeros(self.n)

    def load(self, i: int, state: Snapshot) -> None:
        """Take world ``i``'s new episode from its task, and its first state."""
        task = self.tasks[i]
        self.goal[i] = task._goal
        self._goal_heading[i] = task._goal[2]
        _, _, d, e = task.measure(state)
        self.d[i] = d
        self.phi[i] = abs(e) * math.exp(-d / self.scale)

    def step(self, s: States, actions: np.ndarray, dt: float, out: np.ndarray) -> Step:
        """The reward terms and outcome of every world's step to ``s`` (block in ``out``)."""
        n, g, o, scale = self.n, self.goal, self.options, self.scale
        dx, dy = g[:, 0] - s.x, g[:, 1] - s.y
        pl = s.psi.tolist()
        # every transcendental of the step, in one pass over floats (array_base)
        e = list(map(math.remainder, map(sub, self._goal_heading, pl), repeat(math.tau)))
        if -math.pi in e:  # wrap() gives (−π, π]
            e = [math.pi if v == -math.pi else v for v in e]
        d = list(map(math.hypot, dx.tolist(), dy.tolist()))
        v = np.fromiter(chain(map(math.cos, pl), map(math.sin, pl), map(math.sin, e),
                              map(math.cos, e), d, e,
                              map(math.exp, map(truediv, map(neg, d), repeat(scale)))),
                        float, 7 * n).reshape(7, n)
        c, sn, _, _, dist, err, decay = v
        np.add(c * dx, sn * dy, out=out[:, 0])
        np.subtract(c * dy, sn * dx, out=out[:, 1])
        out[:, 2:5] = v[2:5].T  # sin e, cos e, d
        abs_e = np.abs(err)
        phi = abs_e * decay
        success = (dist < o["position_tolerance"]) & (abs_e < o["heading_tolerance"])
        failure = dist > o["arena"]
        terms = {"progress": (self.d - dist) / scale, "heading": HALF_OVER_PI * (self.phi - phi),
                 "effort": effort(actions), "success": bonus(success, BONUS),
                 "failure": bonus(failure, -BONUS)}
        self.d, self.phi = dist, phi
        return terms, success, failure


class UprightArrays(TaskArrays):
    """:class:`~wmr_mujoco.envs.tasks.upright.StayUpright` over n worlds (target speeds)."""

    def __init__(self, tasks: Sequence[Task]) -> None:
        super().__init__(tasks)
        self.speed = np.ones(self.n)
        self.fall = self.options["fall_lean"]

    def load(self, i: int, state: Snapshot) -> None:
        """Take world ``i``'s new episode from its task, and its first state."""
        self.speed[i] = self.tasks[i].speed

    def step(self, s: States, actions: np.ndarray, dt: float, out: np.ndarray) -> Step:
        """The reward terms and outcome of every world's step to ``s`` (block in ``out``)."""
        x, v = s.extra, self.speed
        lean, u = x["lean"], s.uvr[:, 0]
        for j, col in enumerate((lean, x["lean_rate"], x["steer"], x["steer_rate"], u - v, v)):
            out[:, j] = col
        rel = (u - v) / v
        failure = np.abs(lean) > self.fall
        # (φ / φ_fall) ** 2 as Python computes it (C pow, not φ·φ)
        terms = {"alive": np.full(self.n, dt), "lean": -dt * each(pow, lean / self.fall, 2),
                 "speed": -dt * rel * rel, "effort": effort(actions),
                 "failure": bonus(failure, -BONUS)}
        return terms, np.zeros(self.n, np.bool_), failure

    def succeeded_at_time_limit(self, s: States) -> np.ndarray:
        """Per world: up, and within the speed tolerance."""
        lean, u, v = s.extra["lean"], s.uvr[:, 0], self.speed
        return (np.abs(lean) <= self.fall) & \
            (np.abs(u - v) <= self.options["speed_tolerance"] * v)


#: The array class of each task.
ARRAYS: dict[str, type[TaskArrays]] = {"GoToGoal": GoalArrays, "FollowPath": PathArrays,
                                       "StayUpright": UprightArrays}
