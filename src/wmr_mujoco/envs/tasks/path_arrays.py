""":class:`~wmr_mujoco.envs.tasks.follow.FollowPath` over n worlds, on arrays.

The scalar task's equations (:mod:`wmr_mujoco.envs.tasks.follow`) in the same order of
floating-point operations (:mod:`wmr_mujoco.envs.tasks.array_base`), in a fixed number of
numpy calls per step whatever the number of worlds:

* the walk to the nearest segment: the feet of the point on the segments ``k − 2 … k + 5``
  around each world's last segment ``k`` at once (``t = clip((p − a)·d / |d|², 0, 1)``,
  squared distance ``|a + t d − p|²``); the scalar walk goes forward while the next foot is
  strictly nearer, else backward likewise, so its end is the first column (forward, then
  backward) where the distance stops falling: an ``argmax`` of the comparisons of
  neighbouring columns. A walk that reaches the window's edge (a world moved more than a
  few segments in a step) is walked again by the scalar code;
* the look-ahead samples ``k = bisect_right(s, q) − 1``: guessed from the mean sample
  spacing, checked and completed in a window of 4 samples around the guess (the samples
  are sorted: ``k`` is the window's start plus the number of its samples ``≤ q``, less
  one); a query outside its window is searched by :func:`bisect.bisect_right`.

Each world's path lives in two tables of ``width`` columns per world, indexed ``world ·
width + PAD + sample``: the walk's (a segment's start, increments and ``1/|d|²``, padded
before and after with copies of the first and last segments: a walk stops there, as the
scalar walk stops at the path's ends) and the samples' (``s, x, y, ψ`` and per segment
``Δx, Δy, 1/Δs, Δs, Δψ``; ``s = −∞`` before, ``+∞`` after, so that the windows need no
clipping). Paths are at most :data:`~wmr_mujoco.envs.tasks.base.MAX_LENGTH` long.
"""

from __future__ import annotations

import math
from bisect import bisect_right
from collections.abc import Sequence
from itertools import chain, pairwise, repeat
from operator import sub, truediv

import numpy as np

from wmr_mujoco.envs.stepping import Snapshot
from wmr_mujoco.envs.tasks.array_base import Step, TaskArrays, bonus, effort
from wmr_mujoco.envs.tasks.base import Task
from wmr_mujoco.envs.tasks.follow import _walk
from wmr_mujoco.envs.tasks.goal import BONUS
from wmr_mujoco.envs.worlds import States

#: Rows of the walk's table, per segment: start ``(a_x, a_y)``, vector ``(d_x, d_y)``, 1/|d|².
AX, AY, DX, DY, INV = range(5)
#: Rows of the samples' table: per sample ``s, x, y, ψ``, per segment from it
#: ``Δx, Δy, 1/Δs`` (0 for no length), ``Δs, Δψ``.
S, X, Y, H, GX, GY, IDS, DS, DH = range(9)
#: The walk's window: segments ``k − BACK … k + AHEAD`` of each world's last segment ``k``.
BACK, AHEAD = 2, 5
WINDOW = np.arange(-BACK, AHEAD + 1)[:, None]
#: The walk's end column by ``(forward, backward)`` steps (backward only if no forward
#: step), and whether it may go on beyond the window (its first or last column).
END = np.array([[BACK + f if f else BACK - b for b in range(BACK + 1)]
                for f in range(AHEAD + 1)], np.intp)
EDGE = (END == 0) | (END == BACK + AHEAD)
#: The look-ahead's window: samples ``g − 1 … g + 2`` of a guess ``g``; a count of samples
#: ``≤ q`` of 0 or 4 leaves ``q`` outside it.
LOOK = np.arange(4).reshape(4, 1, 1)
OUTSIDE = np.array([True, False, False, False, True])
#: Padding columns before and after each world's samples.
PAD, PAD_AFTER = BACK, AHEAD


class PathArrays(TaskArrays):
    """:class:`~wmr_mujoco.envs.tasks.follow.FollowPath` over n worlds (module docstring).

    Per world: ``here`` (the flat column of its last segment), ``s`` (its last ``s*``),
    ``base`` (the flat column of its sample 0), ``send`` (its path's last ``s``) and
    ``inv_spacing`` (samples per m: the look-ahead's guess).
    """

    def __init__(self, tasks: Sequence[Task]) -> None:
        super().__init__(tasks)
        n = self.n
        self.end = self.tasks[0].end
        self.dev = self.options["max_deviation"]
        self.ahead = np.array(self.tasks[0]._ahead)
        self.here = np.zeros(n, np.intp)
        self.s = np.zeros(n)
        self.base = np.zeros(n, np.intp)
        self.send = np.zeros(n)
        self.inv_spacing = np.zeros(n)
        self._rows = np.arange(n)
        #: Per world (a column each): the flat columns of sample −1, of the sample after the
        #: last segment and of the last segment (the look-ahead's window and clip).
        self._before = np.zeros((n, 1), np.intp)
        self._after = np.zeros((n, 1), np.intp)
        self._last = np.zeros((n, 1), np.intp)
        # the comparisons of neighbouring columns, each with a stop column preset True
        self._ge = np.ones((BACK + AHEAD + 1, n), np.bool_)
        self._le = np.ones((BACK + AHEAD + 1, n), np.bool_)
        self.width = 0  #: columns per world
        self.walk = np.zeros((5, 0))
        self.samples = np.zeros((9, 0))
        self._alloc(PAD + 2 + PAD_AFTER)

    def _alloc(self, width: int) -> None:
        """Tables of ``width`` columns per world (the loaded worlds kept, their pads grown)."""
        n, old = self.n, self.width
        walk = np.zeros((5, n, width))
        samples = np.zeros((9, n, width))
        samples[S] = math.inf
        if old:
            walk[:, :, :old] = self.walk.reshape(5, n, old)
            walk[:, :, old:] = walk[:, :, old - 1:old]  # the last segment's copies
            samples[:, :, :old] = self.samples.reshape(9, n, old)
            shift = self._rows * (width - old)
            for a in (self.here, self.base):
                a += shift
            for a in (self._before, self._after, self._last):
                a += shift[:, None]
        self.width = width
        self.walk = walk.reshape(5, n * width)
        self.samples = samples.reshape(9, n * width)

    def load(self, i: int, state: Snapshot) -> None:
        """Take world ``i``'s new episode from its task, and its first state."""
        task = self.tasks[i]
        s = task._s
        size = len(s)
        if PAD + size + PAD_AFTER > self.width:
            self._alloc(PAD + size + PAD_AFTER)
        start = i * self.width
        base = start + PAD
        walk = self.walk[:, start:start + self.width]
        segments = np.array(task._segments).T
        walk[:, PAD:PAD + size - 1] = segments
        walk[:, :PAD] = segments[:, :1]
        walk[:, PAD + size - 1:] = segments[:, -1:]
        rows = self.samples[:, start:start + self.width]
        rows[:] = 0.0
        rows[S, :PAD] = -math.inf
        rows[S, PAD + size:] = math.inf
        h = task._heading
        for row, values in ((S, s), (X, task._x), (Y, task._y), (H, h), (GX, task._gx),
                            (GY, task._gy), (IDS, task._ids),
                            (DS, [b - a for a, b in pairwise(s)]),
                            (DH, [b - a for a, b in pairwise(h)])):
            rows[row, PAD:PAD + len(values)] = values
        proj = task.project(state)
        self.here[i] = base + task._proj[2]
        self.s[i] = proj.s
        self.base[i] = base
        self.send[i] = s[-1]
        self.inv_spacing[i] = (size - 1) / s[-1] if s[-1] > 0 else 0.0
        self._before[i], self._after[i] = base - 1, base + size - 1
        self._last[i] = base + size - 2

    def _walk(self, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(flat column of the segment, t)`` per world: the scalar ``_walk`` (docstring).

        Window first (rows: the window's segments, columns: the worlds), so that a world's
        ``x`` and ``y`` broadcast along rows.
        """
        cols = WINDOW + self.here
        ax, ay, dx, dy, inv = self.walk[:, cols]
        t = ((x - ax) * dx + (y - ay) * dy) * inv
        np.copyto(t, 0.0, where=t < 0.0)  # clip: 0 if t < 0, 1 if t > 1 (-0.0, NaN kept)
        np.copyto(t, 1.0, where=t > 1.0)
        ex, ey = ax + t * dx - x, ay + t * dy - y
        d = ex * ex + ey * ey
        ge, le = self._ge, self._le
        np.greater_equal(d[1:], d[:-1], out=ge[:-1])  # forward: stop after row c
        np.greater_equal(d[:-1], d[1:], out=le[1:])  # backward: stop before row c
        forward = ge[BACK:].argmax(axis=0)
        backward = le[BACK::-1].argmax(axis=0)
        row = END[forward, backward]
        worlds = self._rows
        here, t = cols[row, worlds], t[row, worlds]
        far = EDGE[forward, backward]
        if far.tobytes().count(1):  # walks that may go on: the scalar walk
            for w in np.flatnonzero(far).tolist():
                i, t[w] = _walk(self.tasks[w]._segments, float(x[w]), float(y[w]),
                                int(self.here[w] - self.base[w]))
                here[w] = self.base[w] + i
        return here, t

    def _search(self, q: np.ndarray) -> np.ndarray:
        """Flat columns of ``min(bisect_right(s, q) − 1, last segment)``, q (n, …) ≥ 0."""
        guess = (q * self.inv_spacing[:, None]).astype(np.intp)  # ≥ 0
        # the window's first sample, kept inside the table whatever the guess
        lo = np.minimum(guess + self._before, self._after)
        below = (self.samples[S][LOOK + lo] <= q).view(np.uint8)  # window first
        count = below[0] + below[1] + below[2] + below[3]
        k = lo + count - 1
        outside = OUTSIDE[count]
        if outside.tobytes().count(1):
            for w, j in zip(*np.nonzero(outside), strict=True):
                k[w, j] = self.base[w] + bisect_right(self.tasks[w]._s, float(q[w, j])) - 1
        return np.minimum(k, self._last)

    def step(self, s: States, actions: np.ndarray, dt: float, out: np.ndarray) -> Step:
        """The reward terms and outcome of every world's step to ``s`` (block in ``out``)."""
        n, x, y, psi = self.n, s.x, s.y, s.psi
        here, t = self._walk(x, y)
        a = self.samples[:, here]
        rx = x - a[X] - t * a[GX]
        ry = y - a[Y] - t * a[GY]
        heading = a[H] + t * a[DH]
        sp = a[S] + t * a[DS]
        # every transcendental of the step, in one pass over floats (array_base)
        hl, pl = heading.tolist(), psi.tolist()
        hyp = list(map(math.hypot, rx.tolist(), ry.tolist()))
        e = list(map(math.remainder, map(sub, hl, pl), repeat(math.tau)))
        hp = hl + pl
        v = np.fromiter(chain(map(math.cos, hp), map(math.sin, hp), hyp,
                              map(pow, map(truediv, hyp, repeat(self.dev)), repeat(2)),
                              map(math.sin, e), map(math.cos, e)), float, 8 * n)
        cos_h, cos_p, sin_h, sin_p, hyp_, z2, _, _ = v.reshape(8, n)
        # (cross / dev)² = (hypot / dev)²: ``x ** 2`` is ``|x| ** 2``
        cross = np.copysign(hyp_, cos_h * ry - sin_h * rx)
        # the look-ahead points (FollowPath._observe)
        q = np.minimum(sp[:, None] + self.ahead, self.send[:, None])
        g = self.samples[:, self._search(q)]
        tk = (q - g[S]) * g[IDS]
        dx = g[X] + tk * g[GX] - x[:, None]
        dy = g[Y] + tk * g[GY] - y[:, None]
        c, sn = cos_p[:, None], sin_p[:, None]
        np.add(c * dx, sn * dy, out=out[:, 0:10:2])
        np.subtract(c * dy, sn * dx, out=out[:, 1:10:2])
        out[:, 10] = cross
        out[:, 11:13] = v[6 * n:].reshape(2, n).T
        np.subtract(self.end, sp, out=out[:, 13])
        failure = np.abs(cross) > self.dev
        success = np.greater(sp >= self.end, failure)  # and not failure
        terms = {"progress": (sp - self.s) / self.scale, "cross_track": -dt * z2,
                 "effort": effort(actions), "success": bonus(success, BONUS),
                 "failure": bonus(failure, -BONUS)}
        self.here, self.s = here, sp
        return terms, success, failure
