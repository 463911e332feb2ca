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

#: ``(reward terms name -> (n,), success (n,), failure (n,))`` of one step.
Step = tuple[dict[str, np.ndarray], np.ndarray, np.ndarray]


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
    def step(self, s: States, actions: np.ndarray, dt: float, out: np.ndarray) -> Step:
        """The reward terms and outcome of every world's step to ``s``.

        The task's observation block is written into the first columns of ``out`` (n, …).
        """

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
        """Take world ``i``'s new episode from its task, and its first state."""
        task = self.tasks[i]
        self.goal[i] = task._goal
        _, _, d, e = task.measure(state)
        self.d[i] = d
        self.phi[i] = abs(e) * math.exp(-d / self.scale)

    def step(self, s: States, actions: np.ndarray, dt: float, out: np.ndarray) -> Step:
        """The reward terms and outcome of every world's step to ``s`` (block in ``out``)."""
        g, o, scale = self.goal, self.options, self.scale
        dx, dy = g[:, 0] - s.x, g[:, 1] - s.y
        c, sn = each(math.cos, s.psi), each(math.sin, s.psi)
        e = each(math.remainder, g[:, 2] - s.psi, math.tau)
        e[e == -math.pi] = math.pi
        d = each(math.hypot, dx, dy)
        out[:, 0] = c * dx + sn * dy
        out[:, 1] = c * dy - sn * dx
        out[:, 2] = each(math.sin, e)
        out[:, 3] = each(math.cos, e)
        out[:, 4] = d
        phi = np.abs(e) * each(math.exp, -d / scale)
        success = (d < o["position_tolerance"]) & (np.abs(e) < o["heading_tolerance"])
        failure = d > o["arena"]
        terms = {"progress": (self.d - d) / scale, "heading": 0.5 / math.pi * (self.phi - phi),
                 "effort": effort(actions), "success": bonus(success, BONUS),
                 "failure": bonus(failure, -BONUS)}
        self.d, self.phi = d, phi
        return terms, success, failure


#: Columns of :class:`PathArrays`'s table: per sample ``s, x, y, ψ``, and per segment from
#: it ``Δx, Δy, 1/Δs, 1/|d|²`` (the scalar task's lists, bit for bit).
S, X, Y, H, GX, GY, IDS, INV = range(8)


class PathArrays(TaskArrays):
    """:class:`~wmr_mujoco.envs.tasks.follow.FollowPath` over n worlds.

    The worlds' paths are padded into one table of 8 rows (``S`` to ``INV``) by
    ``n · width`` columns (past a path's end ``s = +∞``), indexed ``world · width + sample``:
    8 floats a sample, as the scalar task's own lists hold (the paths' length is bounded by
    :data:`~wmr_mujoco.envs.tasks.base.MAX_LENGTH`). Per world the last segment ``k`` and
    arc length ``s*`` are kept. A step walks the segments from ``k`` as the scalar task's
    ``_walk``: the feet on segments ``k − 1 … k + 2`` at once, then, for the worlds whose
    walk goes on past them, one segment per pass; the look-ahead points' samples are found
    by :meth:`_search`.
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
        self.ds = np.ones(n)  #: each path's mean sample spacing, m (the look-ahead's guess)
        self.width = 0  #: samples per world
        self._alloc(2)

    def _alloc(self, width: int) -> None:
        """Rows of ``width`` samples per world (the old ones kept)."""
        n, old = self.n, self.width
        table = np.zeros((8, n, width))
        table[S] = math.inf
        if old:
            table[:, :, :old] = self.table.reshape(8, n, old)
        self.width = width
        self.table = table.reshape(8, n * width)
        self.base = np.arange(n) * width

    def load(self, i: int, state: Snapshot) -> None:
        """Take world ``i``'s new episode from its task, and its first state."""
        task = self.tasks[i]
        s = np.array(task._s)
        size = len(s)
        need = size + 2  # past the end: s = +∞ (a search stops there)
        if need > self.width:
            self._alloc(need)
        rows = self.table[:, i * self.width:(i + 1) * self.width]
        rows[:] = 0.0
        rows[S] = math.inf
        for col, values in ((S, s), (X, task._x), (Y, task._y), (H, task._heading),
                            (GX, task._gx), (GY, task._gy), (IDS, task._ids),
                            (INV, [g[4] for g in task._segments])):
            rows[col, :len(values)] = values
        proj = task.project(state)
        self.k[i] = task._proj[2]
        self.s[i] = proj.s
        self.last[i] = size - 2
        self.send[i] = s[-1]
        self.ds[i] = s[-1] / (size - 1) if s[-1] > 0 else 1.0

    def _foot(self, k: np.ndarray, px: np.ndarray, py: np.ndarray
              ) -> tuple[np.ndarray, np.ndarray]:
        """``(squared distance, t)`` of each world's foot on its segment(s) ``k`` (n, …)."""
        base = self.base if k.ndim == 1 else self.base[:, None]
        g = self.table[:, base + k]
        ax, ay, dx, dy = g[X], g[Y], g[GX], g[GY]
        t = ((px - ax) * dx + (py - ay) * dy) * g[INV]
        t = np.where(t < 0.0, 0.0, np.where(t > 1.0, 1.0, t))
        ex, ey = ax + t * dx - px, ay + t * dy - py
        return ex * ex + ey * ey, t

    def _walk(self, px: np.ndarray, py: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(segment, t)`` per world: the scalar ``_walk`` from each world's last segment."""
        k, last = self.k, self.last
        near = np.minimum(np.maximum(k[:, None] + np.arange(-1, 3), 0), last[:, None])
        d, u = self._foot(near, px[:, None], py[:, None])
        f1 = (k + 1 <= last) & ~(d[:, 2] >= d[:, 1])  # forward one segment
        f2 = f1 & (k + 2 <= last) & ~(d[:, 3] >= d[:, 2])  # and two
        back = ~f1 & (k >= 1) & ~(d[:, 0] >= d[:, 1])  # else backward one
        col = np.where(f2, 3, np.where(f1, 2, np.where(back, 0, 1)))
        r = np.arange(self.n)
        i, best, t = k + col - 1, d[r, col], u[r, col]
        for step, go in ((1, f2 & (i + 1 <= last)), (-1, back & (i >= 1))):
            j = i + step
            while go.any():  # the walks that go on: one segment per pass
                j = np.where(go, j, i)
                dj, uj = self._foot(j, px, py)
                better = go & ~(dj >= best)
                i, best, t = (np.where(better, j, i), np.where(better, dj, best),
                              np.where(better, uj, t))
                j = j + step
                go = better & ((j <= last) if step > 0 else (j >= 0))
        return i, t

    def _search(self, q: np.ndarray, i: np.ndarray) -> np.ndarray:
        """``bisect_right(s, q) − 1`` per world and look-ahead (q (n, 5) ≥ ``s[i]``).

        Guessed from the mean sample spacing, then moved until ``s[k] ≤ q < s[k + 1]``
        (exact whatever the guess: the samples are sorted).
        """
        flat = self.table[S]
        base = self.base[:, None]
        k = np.minimum(np.maximum((q / self.ds[:, None]).astype(np.intp), i[:, None]),
                       self.last[:, None] + 1)
        for step in (1, -1):
            move = (flat[base + k + 1] <= q) if step > 0 else (flat[base + k] > q)
            while move.any():
                k = k + step * move
                move &= (flat[base + k + 1] <= q) if step > 0 else (flat[base + k] > q)
        return k

    def step(self, s: States, actions: np.ndarray, dt: float, out: np.ndarray) -> Step:
        """The reward terms and outcome of every world's step to ``s`` (block in ``out``)."""
        x, y, psi = s.x, s.y, s.psi
        i, t = self._walk(x, y)
        here = self.base + i
        a, b = self.table[:, here], self.table[:, here + 1]
        rx = x - a[X] - t * a[GX]
        ry = y - a[Y] - t * a[GY]
        heading = a[H] + t * (b[H] - a[H])
        side = each(math.cos, heading) * ry - each(math.sin, heading) * rx
        sp = a[S] + t * (b[S] - a[S])
        cross = np.copysign(each(math.hypot, rx, ry), side)
        # the look-ahead points (FollowPath._observe): k = bisect_right(s, q) − 1
        q = np.minimum(sp[:, None] + self.ahead, self.send[:, None])
        k = self._search(q, i)
        g = self.table[:, self.base[:, None] + np.minimum(k, self.last[:, None])]
        tk = (q - g[S]) * g[IDS]
        dx = g[X] + tk * g[GX] - x[:, None]
        dy = g[Y] + tk * g[GY] - y[:, None]
        c, sn = each(math.cos, psi)[:, None], each(math.sin, psi)[:, None]
        out[:, 0:10:2] = c * dx + sn * dy
        out[:, 1:10:2] = c * dy - sn * dx
        e = each(math.remainder, heading - psi, math.tau)
        out[:, 10] = cross
        out[:, 11] = each(math.sin, e)
        out[:, 12] = each(math.cos, e)
        out[:, 13] = self.end - sp
        failure = np.abs(cross) > self.dev
        success = (sp >= self.end) & ~failure
        z = cross / self.dev
        terms = {"progress": (sp - self.s) / self.scale, "cross_track": -dt * (z * z),
                 "effort": effort(actions), "success": bonus(success, BONUS),
                 "failure": bonus(failure, -BONUS)}
        self.k, self.s = i, sp
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
        z = lean / self.fall
        failure = np.abs(lean) > self.fall
        terms = {"alive": np.full(self.n, dt), "lean": -dt * (z * z), "speed": -dt * rel * rel,
                 "effort": effort(actions), "failure": bonus(failure, -BONUS)}
        return terms, np.zeros(self.n, np.bool_), failure

    def succeeded_at_time_limit(self, s: States) -> np.ndarray:
        """Per world: up, and within the speed tolerance."""
        lean, u, v = s.extra["lean"], s.uvr[:, 0], self.speed
        return (np.abs(lean) <= self.fall) & \
            (np.abs(u - v) <= self.options["speed_tolerance"] * v)


#: The array class of each task.
ARRAYS: dict[str, type[TaskArrays]] = {"GoToGoal": GoalArrays, "FollowPath": PathArrays,
                                       "StayUpright": UprightArrays}
