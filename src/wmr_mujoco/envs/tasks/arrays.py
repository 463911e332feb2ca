"""The tasks' step math over n worlds at once, on arrays with a leading world axis.

The native vector environment (:mod:`wmr_mujoco.envs.vector`) computes each step's task
block of the observation, reward terms and outcome once for every world with these
classes; the single environment keeps its scalar code (:mod:`~wmr_mujoco.envs.tasks.goal`,
:mod:`~wmr_mujoco.envs.tasks.follow`, :mod:`~wmr_mujoco.envs.tasks.upright`, whose
docstrings give the equations). Each class here is the same equations, in the same order
of floating-point operations (numpy's elementwise ``+ − × ÷`` round as Python's floats do;
``sin``, ``cos``, ``exp``, ``hypot``, ``atan2`` and ``remainder`` run through :mod:`math`,
:func:`~wmr_mujoco.envs.worlds.each`), so every result equals the scalar task's bit for bit
(``tests/envs/test_vector.py`` compares them).

A world's episode (goal, path, target speed) is drawn by its scalar task at the world's
reset; :meth:`TaskArrays.load` then copies it, and the first state's measurement, into
row ``i``.
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from collections.abc import Sequence

import numpy as np

from wmr_mujoco.envs.stepping import Snapshot
from wmr_mujoco.envs.tasks.base import EFFORT, Task
from wmr_mujoco.envs.tasks.goal import BONUS
from wmr_mujoco.envs.worlds import States, each

#: ``(obs (n, k), reward terms name -> (n,), success (n,), failure (n,))`` of one step.
Step = tuple[np.ndarray, dict[str, np.ndarray], np.ndarray, np.ndarray]


def effort(actions: np.ndarray) -> np.ndarray:
    """``−EFFORT mean(a²)`` per world, summed channel by channel as the scalar code does."""
    total = actions[:, 0] * actions[:, 0]
    for j in range(1, actions.shape[1]):
        total = total + actions[:, j] * actions[:, j]
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
    def step(self, s: States, actions: np.ndarray, dt: float) -> Step:
        """The task block, reward terms and outcome of every world's step to ``s``."""

    def succeeded_at_time_limit(self, s: States) -> np.ndarray:
        """Per world: whether running to the time limit counts as a success (default no)."""
        return np.zeros(self.n, np.bool_)


class GoalArrays(TaskArrays):
    """:class:`~wmr_mujoco.envs.tasks.goal.GoToGoal` over n worlds.

    Keeps per world the goal ``(x_g, y_g, ψ_g)``, the last distance ``d₋`` and the last
    heading potential term ``|e_ψ| e^{−d/L}``.
    """

    def __init__(self, tasks: Sequence[Task]) -> None:
        super().__init__(tasks)
        self.goal = np.zeros((self.n, 3))
        self.d = np.zeros(self.n)
        self.phi = np.zeros(self.n)

    def load(self, i: int, state: Snapshot) -> None:
        task = self.tasks[i]
        self.goal[i] = task._goal
        _, _, d, e = task.measure(state)
        self.d[i] = d
        self.phi[i] = abs(e) * math.exp(-d / self.scale)

    def step(self, s: States, actions: np.ndarray, dt: float) -> Step:
        g, o, scale = self.goal, self.options, self.scale
        dx, dy = g[:, 0] - s.x, g[:, 1] - s.y
        c, sn = each(math.cos, s.psi), each(math.sin, s.psi)
        e = each(math.remainder, g[:, 2] - s.psi, math.tau)
        e[e == -math.pi] = math.pi
        d = each(math.hypot, dx, dy)
        obs = np.stack([c * dx + sn * dy, c * dy - sn * dx, each(math.sin, e),
                        each(math.cos, e), d], axis=1)
        phi = np.abs(e) * each(math.exp, -d / scale)
        success = (d < o["position_tolerance"]) & (np.abs(e) < o["heading_tolerance"])
        failure = d > o["arena"]
        terms = {"progress": (self.d - d) / scale, "heading": 0.5 / math.pi * (self.phi - phi),
                 "effort": effort(actions), "success": bonus(success, BONUS),
                 "failure": bonus(failure, -BONUS)}
        self.d, self.phi = d, phi
        return obs, terms, success, failure


class PathArrays(TaskArrays):
    """:class:`~wmr_mujoco.envs.tasks.follow.FollowPath` over n worlds.

    The worlds' paths are padded into ``(n, K)`` arrays (``s``, ``x``, ``y``, ``ψ``; past a
    path's end ``s = +∞``); per segment ``Δx``, ``Δy``, ``1/Δs``, ``1/|d|²``. Per world the
    last segment ``k`` and arc length ``s*`` are kept; a step walks the segments from ``k``
    (all worlds at once, while any world's walk goes on) as the scalar task's ``_walk``.
    """

    def __init__(self, tasks: Sequence[Task]) -> None:
        super().__init__(tasks)
        n = self.n
        self.end = self.tasks[0].end
        self.dev = self.options["max_deviation"]
        self.ahead = np.array(self.tasks[0]._ahead)
        self.k = np.zeros(n, np.intp)
        self.s = np.zeros(n)
        self.last = np.zeros(n, np.intp)
        self.send = np.zeros(n)
        self.width = 0  #: samples per row
        self.window = 1  #: samples a look-ahead may pass beyond a world's segment
        self._alloc(2)

    def _alloc(self, width: int) -> None:
        """Rows of ``width`` samples (the old rows kept)."""
        n, old = self.n, self.width
        grown = {}
        for name, fill in (("S", math.inf), ("X", 0.0), ("Y", 0.0), ("H", 0.0), ("GX", 0.0),
                           ("GY", 0.0), ("IDS", 0.0), ("INV", 0.0)):
            a = np.full((n, width), fill)
            if old:
                a[:, :old] = getattr(self, name)
            grown[name] = a
        self.__dict__.update(grown)
        self.width = width

    def load(self, i: int, state: Snapshot) -> None:
        task = self.tasks[i]
        s = np.array(task._s)
        size = len(s)
        reach = np.searchsorted(s, s[1:] + self.ahead[-1], side="right") - np.arange(size - 1)
        self.window = max(self.window, int(reach.max()) + 1)
        need = size + self.window + 1
        if need > self.width:
            self._alloc(need)
        for name, values in (("S", s), ("X", task._x), ("Y", task._y), ("H", task._heading),
                             ("GX", task._gx), ("GY", task._gy), ("IDS", task._ids),
                             ("INV", [g[4] for g in task._segments])):
            row = getattr(self, name)[i]
            row[len(values):] = math.inf if name == "S" else 0.0
            row[:len(values)] = values
        proj = task.project(state)
        self.k[i] = task._proj[2]
        self.s[i] = proj.s
        self.last[i] = size - 2
        self.send[i] = s[-1]

    def _foot(self, k: np.ndarray, px: np.ndarray, py: np.ndarray
              ) -> tuple[np.ndarray, np.ndarray]:
        """``(squared distance, t)`` of each world's foot on its segment ``k``."""
        r = self._r
        ax, ay, dx, dy = self.X[r, k], self.Y[r, k], self.GX[r, k], self.GY[r, k]
        t = ((px - ax) * dx + (py - ay) * dy) * self.INV[r, k]
        t = np.where(t < 0.0, 0.0, np.where(t > 1.0, 1.0, t))
        ex, ey = ax + t * dx - px, ay + t * dy - py
        return ex * ex + ey * ey, t

    def _walk(self, px: np.ndarray, py: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(segment, t)`` per world: the scalar ``_walk`` from each world's last segment."""
        start = i = self.k
        best, t = self._foot(i, px, py)
        for step, bound in ((1, self.last), (-1, None)):
            j = i + step
            go = (j <= bound) if bound is not None else (j >= 0) & (i == start)
            while go.any():
                j = np.where(go, j, i)
                d, u = self._foot(j, px, py)
                better = go & ~(d >= best)
                i, best, t = np.where(better, j, i), np.where(better, d, best), \
                    np.where(better, u, t)
                j = j + step
                go = better & ((j <= bound) if bound is not None else (j >= 0))
        return i, t

    def step(self, s: States, actions: np.ndarray, dt: float) -> Step:
        self._r = r = np.arange(self.n)
        x, y, psi = s.x, s.y, s.psi
        i, t = self._walk(x, y)
        S, H = self.S, self.H
        rx = x - self.X[r, i] - t * self.GX[r, i]
        ry = y - self.Y[r, i] - t * self.GY[r, i]
        h0 = H[r, i]
        heading = h0 + t * (H[r, i + 1] - h0)
        side = each(math.cos, heading) * ry - each(math.sin, heading) * rx
        s0 = S[r, i]
        sp = s0 + t * (S[r, i + 1] - s0)
        cross = np.copysign(each(math.hypot, rx, ry), side)
        # the look-ahead points (FollowPath._observe): k = bisect_right(s, q) − 1
        q = np.minimum(sp[:, None] + self.ahead, self.send[:, None])
        cols = i[:, None] + np.arange(self.window)
        near = S[r[:, None], cols]
        k = i[:, None] - 1 + (near[:, None, :] <= q[:, :, None]).sum(axis=2)
        k = np.minimum(k, self.last[:, None])
        rr = r[:, None]
        tk = (q - S[rr, k]) * self.IDS[rr, k]
        dx = self.X[rr, k] + tk * self.GX[rr, k] - x[:, None]
        dy = self.Y[rr, k] + tk * self.GY[rr, k] - y[:, None]
        c, sn = each(math.cos, psi)[:, None], each(math.sin, psi)[:, None]
        pts = np.stack([c * dx + sn * dy, c * dy - sn * dx], axis=2).reshape(self.n, -1)
        e = each(math.remainder, heading - psi, math.tau)
        obs = np.concatenate([pts, np.stack([cross, each(math.sin, e), each(math.cos, e),
                                             self.end - sp], axis=1)], axis=1)
        failure = np.abs(cross) > self.dev
        success = (sp >= self.end) & ~failure
        z = cross / self.dev
        terms = {"progress": (sp - self.s) / self.scale, "cross_track": -dt * (z * z),
                 "effort": effort(actions), "success": bonus(success, BONUS),
                 "failure": bonus(failure, -BONUS)}
        self.k, self.s = i, sp
        return obs, terms, success, failure


class UprightArrays(TaskArrays):
    """:class:`~wmr_mujoco.envs.tasks.upright.StayUpright` over n worlds (target speeds)."""

    def __init__(self, tasks: Sequence[Task]) -> None:
        super().__init__(tasks)
        self.speed = np.ones(self.n)
        self.fall = self.options["fall_lean"]

    def load(self, i: int, state: Snapshot) -> None:
        self.speed[i] = self.tasks[i].speed

    def step(self, s: States, actions: np.ndarray, dt: float) -> Step:
        x, v = s.extra, self.speed
        lean, u = x["lean"], s.uvr[:, 0]
        obs = np.stack([lean, x["lean_rate"], x["steer"], x["steer_rate"], u - v, v], axis=1)
        rel = (u - v) / v
        z = lean / self.fall
        failure = np.abs(lean) > self.fall
        terms = {"alive": np.full(self.n, dt), "lean": -dt * (z * z), "speed": -dt * rel * rel,
                 "effort": effort(actions), "failure": bonus(failure, -BONUS)}
        return obs, terms, np.zeros(self.n, np.bool_), failure

    def succeeded_at_time_limit(self, s: States) -> np.ndarray:
        lean, u, v = s.extra["lean"], s.uvr[:, 0], self.speed
        return (np.abs(lean) <= self.fall) & \
            (np.abs(u - v) <= self.options["speed_tolerance"] * v)


#: The array class of each task.
ARRAYS: dict[str, type[TaskArrays]] = {"GoToGoal": GoalArrays, "FollowPath": PathArrays,
                                       "StayUpright": UprightArrays}
