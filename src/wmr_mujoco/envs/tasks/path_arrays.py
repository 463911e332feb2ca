""":class:`~wmr_mujoco.envs.tasks.follow.FollowPath` over n worlds, on arrays.

The scalar task's equations (:mod:`wmr_mujoco.envs.tasks.follow`) in the same order of
floating-point operations (:mod:`wmr_mujoco.envs.tasks.array_base`), in a fixed number of
numpy calls per step whatever the number of worlds, the ``x`` and ``y`` parts of a
quantity stacked so that one call computes both:

* the walk to the nearest segment: the feet of the point on the segments ``k − 1 … k + 4``
  around each world's last segment ``k`` at once (``t = clip((p − a)·d / |d|², 0, 1)``,
  squared distance ``|a + t d − p|²``); the scalar walk goes forward while the next foot is
  strictly nearer, else backward likewise, so its end is the first row (forward, then
  backward) where the distance stops falling: an ``argmax`` of the comparisons of
  neighbouring rows. A walk that reaches the window's edge (a world moved more than three
  segments forward or one back in a step: about 1 % of the worlds' steps) is walked again
  by the scalar code. The window holds, per candidate segment, ``p − a − t d``, ``t`` and
  the segment's ``s, ψ, Δs, Δψ``, so that one gather picks every value of the segment
  walked to;
* the look-ahead samples ``k = min(bisect_right(s, q) − 1, last segment)``: guessed as
  the walk's segment plus the look-ahead distance over the mean sample spacing (exact for
  evenly spaced samples, up to one sample), checked and completed in a window of 4
  samples around the guess (the samples are sorted: ``k`` is the window's start plus the
  number of its samples ``≤ q``, less one); a query outside its window is searched by
  :func:`bisect.bisect_right`. The search's copy of the samples holds ``−∞`` before them
  and ``+∞`` from the last one on: the windows need no clipping, and ``k`` never passes
  the last segment.

Each world's path lives in tables of ``width`` records per world, indexed ``world · width
+ PAD + sample``, a record's values side by side (a gather reads one or two cache lines a
record; the physics of the other worlds has evicted the tables since the last step): the
walk's (per segment ``s, ψ, Δs, Δψ``, its start, increments and ``1/|d|²``, padded before
and after with copies of the first and last segments: a walk stops there, as the scalar
walk stops at the path's ends), the samples' (``s``, then per segment from it ``1/Δs``
(0 for no length), then ``x, y, Δx, Δy``) and the search's ``s``. Paths are at most
:data:`~wmr_mujoco.envs.tasks.base.MAX_LENGTH` long.
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

#: Fields of the walk's records, per segment: ``s, ψ, Δs, Δψ`` (the projection's
#: interpolation), start ``(a_x, a_y)``, vector ``(d_x, d_y)``, ``1/|d|²``.
S, H, DS, DH, AX, AY, DX, DY, INV = range(9)
#: Fields of the samples' records: ``s``, ``1/Δs``, ``x, y``, ``Δx, Δy``.
QS, IDS, X, Y, GX, GY = range(6)
#: Rows of the walk's window: ``p − a − t d`` (x, y), ``t``, then the walk's fields.
RX, RY, T, W0 = range(4)
#: The walk's window: segments ``k − BACK … k + AHEAD`` of each world's last segment ``k``.
BACK, AHEAD = 1, 4
WINDOW = np.arange(-BACK, AHEAD + 1)[:, None]
#: The walk's end row by ``(forward, backward)`` steps (backward only if no forward step);
#: an end on the window's first or last row may go on beyond the window.
END = np.array([[BACK + f if f else BACK - b for b in range(BACK + 1)]
                for f in range(AHEAD + 1)], np.intp)
EDGES = (0, BACK + AHEAD)
#: Padding records before and after each world's samples.
PAD, PAD_AFTER = BACK, AHEAD
#: Samples in the look-ahead's window, and the matrix that counts its samples ``≤ q``.
LOOK = 4
ONES = np.ones(LOOK, np.uint8)


class PathArrays(TaskArrays):
    """:class:`~wmr_mujoco.envs.tasks.follow.FollowPath` over n worlds (module docstring).

    Per world: ``here`` (the flat index of its last segment), ``s`` (its last ``s*``),
    ``base`` (the flat index of its sample 0) and ``send`` (its path's last ``s``, a
    column).
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
        self.send = np.zeros((n, 1))
        self._rows = np.arange(n)
        #: Per world and look-ahead distance ``a``: the look-ahead window's start less one
        #: from the walk's segment (``⌊a / mean spacing⌋ − 2``); per world the largest
        #: (the window then starts at the last segment, before the ``+∞``).
        self.skip = np.zeros((n, len(self.ahead)), np.intp)
        self._after = np.zeros((n, 1), np.intp)
        rows = BACK + AHEAD + 1
        self._win = win = np.zeros((W0 + 9, rows, n))
        g = win[W0:]
        #: Views of the window: ``p − a`` (then ``p − a − t d``), ``t``, the walk's fields
        #: (all, ``a``, ``d``, ``1/|d|²``), the clip's mask; the gathered records.
        self._views = (win[RX:RY + 1], win[T], g, g[AX:AY + 1], g[DX:DY + 1], g[INV],
                       np.zeros((rows, n), np.bool_))
        self._records = np.zeros((rows, n, 9))
        #: The flat window (rows ``RX`` …, window row · n + world) and the flat index of
        #: the walk's end row of each world by ``(forward, backward)`` steps.
        self._flat = win.reshape(W0 + 9, rows * n)
        self._end = END * n
        #: The comparisons of neighbouring window rows, each with a stop row preset True.
        self._ge = np.ones((rows, n), np.bool_)
        self._le = np.ones((rows, n), np.bool_)
        #: The look-ahead's gathered records, and their fields first.
        self._looked = np.zeros((n, len(self.ahead), 6))
        self._fields = np.zeros((6, n, len(self.ahead)))
        self.width = 0  #: records per world
        self.walk = np.zeros((0, 9))
        self.samples = np.zeros((0, 6))
        self.search = np.zeros(0)
        self._alloc(PAD + 2 + PAD_AFTER)

    def _alloc(self, width: int) -> None:
        """Tables of ``width`` records per world (the loaded worlds kept, their pads grown)."""
        n, old = self.n, self.width
        walk = np.zeros((n, width, 9))
        samples = np.zeros((n, width, 6))
        search = np.full((n, width), math.inf)
        if old:
            walk[:, :old] = self.walk.reshape(n, old, 9)
            walk[:, old:] = walk[:, old - 1:old]  # the last segment's copies
            samples[:, :old] = self.samples.reshape(n, old, 6)
            search[:, :old] = self.search.reshape(n, old)
            shift = self._rows * (width - old)
            for a in (self.here, self.base):
                a += shift
            self._after += shift[:, None]
        self.width = width
        self.walk = walk.reshape(n * width, 9)
        self.samples = samples.reshape(n * width, 6)
        self.search = search.reshape(n * width)
        #: The look-ahead's windows: ``_looks[j]`` is ``search[j + 1 : j + 1 + LOOK]``.
        self._looks = np.lib.stride_tricks.sliding_window_view(self.search[1:], LOOK)

    def load(self, i: int, state: Snapshot) -> None:
        """Take world ``i``'s new episode from its task, and its first state."""
        task = self.tasks[i]
        s, h = task._s, task._heading
        size = len(s)
        if PAD + size + PAD_AFTER > self.width:
            self._alloc(PAD + size + PAD_AFTER)
        start = i * self.width
        base = start + PAD
        walk = self.walk[start:start + self.width]
        walk[PAD:PAD + size - 1, :AX] = np.array(
            (s[:-1], h[:-1], [b - a for a, b in pairwise(s)],
             [b - a for a, b in pairwise(h)])).T
        walk[PAD:PAD + size - 1, AX:] = task._segments
        walk[:PAD] = walk[PAD]
        walk[PAD + size - 1:] = walk[PAD + size - 2]
        records = self.samples[start:start + self.width]
        records[:] = 0.0
        for field, values in ((QS, s), (IDS, task._ids), (X, task._x), (Y, task._y),
                              (GX, task._gx), (GY, task._gy)):
            records[PAD:PAD + len(values), field] = values
        search = self.search[start:start + self.width]
        search[:PAD] = -math.inf
        search[PAD:PAD + size - 1] = s[:-1]
        search[PAD + size - 1:] = math.inf
        proj = task.project(state)
        self.here[i] = base + task._proj[2]
        self.s[i] = proj.s
        self.base[i] = base
        self.send[i] = s[-1]
        self.skip[i] = (self.ahead * ((size - 1) / s[-1] if s[-1] > 0 else 0.0)
                        ).astype(np.intp) - 2
        self._after[i] = base + size - 3

    def _walk(self, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each world's segment walked to from ``here`` (the scalar ``_walk``).

        Returns its flat index and its window values (rows :data:`RX` …, worlds); module
        docstring. ``p``: the worlds' ``(x, y)``, (2, n). Window first (rows: the window's segments,
        columns: the worlds), so that a world's ``x`` and ``y`` broadcast along rows.
        """
        cols = WINDOW + self.here
        r, t, g, a, d, inv, below = self._views
        records = self._records
        np.take(self.walk, cols, axis=0, out=records, mode="clip")  # the indices are in range
        np.copyto(g, records.transpose(2, 0, 1))
        p3 = p[:, None]
        np.subtract(p3, a, out=r)  # p − a
        m = r * d
        np.add(m[0], m[1], out=t)
        t *= inv
        # clip: 0 if t < 0 (−0.0 kept: not np.maximum, whose sign of a tie is the SIMD
        # code's), 1 if t > 1 (np.minimum: a tie is 1.0 either way); NaN kept
        np.less(t, 0.0, out=below)
        np.putmask(t, below, 0.0)
        np.minimum(t, 1.0, out=t)
        td = t * d
        e = a + td
        e -= p3
        e *= e
        dist = e[0] + e[1]
        r -= td  # p − a − t d
        ge, le = self._ge, self._le
        np.greater_equal(dist[1:], dist[:-1], out=ge[:-1])  # forward: stop after row c
        np.greater_equal(dist[:-1], dist[1:], out=le[1:])  # backward: stop before row c
        forward, backward = ge[BACK:].argmax(axis=0), le[BACK::-1].argmax(axis=0)
        flat = self._end[forward, backward] + self._rows
        here, at = cols.ravel()[flat], self._flat[:, flat]
        ends = END[forward, backward].tolist()
        if EDGES[0] in ends or EDGES[1] in ends:  # walks that may go on: the scalar walk
            for w in [w for w, r in enumerate(ends) if r in EDGES]:
                x, y = p[:, w].tolist()
                i, tw = _walk(self.tasks[w]._segments, x, y, int(self.here[w] - self.base[w]))
                here[w] = self.base[w] + i
                at[W0:, w] = self.walk[here[w]]
                ax, ay, dx, dy = at[W0 + AX:W0 + DY + 1, w].tolist()
                at[:W0, w] = (x - ax - tw * dx, y - ay - tw * dy, tw)
        return here, at

    def _search(self, q: np.ndarray, here: np.ndarray) -> np.ndarray:
        """Flat indices of ``min(bisect_right(s, q) − 1, last segment)``, q (n, …) ≥ 0.

        ``here``: flat indices of a sample at or before each world's queries.
        """
        j = self.skip + here[:, None]
        j = np.minimum(j, self._after, out=j)  # the window: j + 1 … j + LOOK
        count = (self._looks[j] <= q[..., None]).view(np.uint8) @ ONES
        k = j + count
        counts = count.tobytes()
        if 0 in counts or LOOK in counts:  # q outside its window: bisect
            for w, c in zip(*np.nonzero((count == 0) | (count == LOOK)), strict=True):
                task = self.tasks[w]
                k[w, c] = self.base[w] + min(bisect_right(task._s, float(q[w, c])) - 1,
                                             len(task._s) - 2)
        return k

    def step(self, s: States, actions: np.ndarray, dt: float, out: np.ndarray) -> Step:
        """The reward terms and outcome of every world's step to ``s`` (block in ``out``)."""
        n = self.n
        p = np.array((s.x, s.y))
        here, at = self._walk(p)
        sh = at[W0 + S:W0 + H + 1] + at[T] * at[W0 + DS:W0 + DH + 1]  # s*, ψ_path
        sp = sh[0]
        # every transcendental of the step, in one pass over floats (array_base)
        hl, pl = sh[1].tolist(), s.psi.tolist()
        rx, ry = at[RX:RY + 1].tolist()
        hyp = list(map(math.hypot, rx, ry))
        e = list(map(math.remainder, map(sub, hl, pl), repeat(math.tau)))
        hp = hl + pl
        v = np.fromiter(chain(map(math.cos, hp), map(math.sin, hp), hyp,
                              map(pow, map(truediv, hyp, repeat(self.dev)), repeat(2)),
                              map(math.sin, e), map(math.cos, e)), float, 8 * n
                        ).reshape(8, n)
        # cross = copysign(hypot, cos ψ_path r_y − sin ψ_path r_x); |cross| = hypot, and
        # (cross / dev)² = (hypot / dev)²: ``x ** 2`` is ``|x| ** 2``
        side = v[0:3:2] * at[RY::-1]
        np.copysign(v[4], side[0] - side[1], out=out[:, 10])
        # the look-ahead points (FollowPath._observe), (x, y) stacked: (2, n, 5)
        q = sp[:, None] + self.ahead
        np.minimum(q, self.send, out=q)
        np.take(self.samples, self._search(q, here), axis=0, out=self._looked, mode="clip")
        g = self._fields
        np.copyto(g, self._looked.transpose(2, 0, 1))
        tk = q - g[QS]
        tk *= g[IDS]
        d = tk * g[GX:GY + 1]
        d += g[X:Y + 1]  # x_k + t Δx_k
        d -= p[:, :, None]
        rot = v[1:4:2, None, :, None] * d  # [[c dx, c dy], [s dx, s dy]], c, s = cos, sin ψ
        np.add(rot[0, 0], rot[1, 1], out=out[:, 0:10:2])
        np.subtract(rot[0, 1], rot[1, 0], out=out[:, 1:10:2])
        out[:, 11:13] = v[6:8].T
        np.subtract(self.end, sp, out=out[:, 13])
        failure = v[4] > self.dev  # |cross| > dev
        success = np.greater(sp >= self.end, failure)  # and not failure
        terms = {"progress": (sp - self.s) / self.scale, "cross_track": -dt * v[5],
                 "effort": effort(actions), "success": bonus(success, BONUS),
                 "failure": bonus(failure, -BONUS)}
        self.here, self.s = here, sp
        return terms, success, failure
