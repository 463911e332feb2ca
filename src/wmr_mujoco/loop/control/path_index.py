"""The point queries of a :class:`~wmr_mujoco.loop.control.paths.Path`, on Python floats.

A control loop asks a path a few questions every period (the point at an arc length,
the point nearest the robot, the lookahead point), each about one point: numpy's
per-call cost, not its arithmetic, would dominate them. :class:`PathIndex` answers them
as rows ``(s, x, y, heading, curvature)`` with the floats of the array formulas the
path's docstrings state (``np.interp``, the polyline projection, the lookahead scan;
``tests/loop/control/test_paths.py`` checks them against those formulas):

* the point at ``s``: :func:`~wmr_mujoco.loop.control.polyline.interp` of every column;
* the nearest point: the window's feet (:class:`~wmr_mujoco.loop.control.polyline.Finder`),
  the answers kept by their arguments (at most :data:`MEMO`; a loop's cross-track pass
  asks its controller's questions again);
* the lookahead point: the scan of the samples ahead, skipping those surely inside the
  circle (:func:`~wmr_mujoco.loop.control.polyline.reach`,
  :func:`~wmr_mujoco.loop.control.polyline.first_beyond`).
"""

from __future__ import annotations

import math

import numpy as np

from wmr_mujoco.loop.control import polyline

#: Closest-point answers an index keeps (then it forgets them all): two runs' worth.
MEMO = 8192
#: A row: ``(s, x, y, heading, curvature)``.
Row = tuple[float, float, float, float, float]


class PathIndex:
    """A path's samples, kept for point queries (module docstring).

    Args:
        s: ``(N,)`` increasing arc lengths, m.
        xy: ``(N, 2)`` positions, m.
        heading: ``(N,)`` headings, rad.
        curvature: ``(N,)`` curvatures, 1/m.
        closed: whether arc lengths wrap.
    """

    def __init__(self, s: np.ndarray, xy: np.ndarray, heading: np.ndarray,
                 curvature: np.ndarray, closed: bool) -> None:
        self.s = s
        self.closed = closed
        self.seg = polyline.segments(xy)
        self.lists = tuple(a.tolist() for a in (s, xy[:, 0], xy[:, 1], heading, curvature))
        self.length = self.lists[0][-1]
        self.finder = polyline.Finder(self.seg)
        self.memo: dict[tuple[float, float, float | None, float], Row] = {}
        self._reach: tuple[float, float] | None = None

    def wrap(self, s: float) -> float:
        """``s`` wrapped (closed) or clipped (open): ``np.mod``'s, ``np.clip``'s float."""
        if self.closed:
            return float(s) % self.length if math.isfinite(s) else math.nan
        return float(s) if s != s else min(max(float(s), 0.0), self.length)

    def wrap_array(self, s: np.ndarray) -> np.ndarray:
        """:meth:`wrap` of an array."""
        if self.closed:
            return np.mod(s, self.length)
        return np.minimum(np.maximum(s, 0.0), self.s[-1])

    def at(self, s: float) -> Row:
        """The row at arc length ``s`` (wrapped or clipped)."""
        s = self.wrap(s)
        return (s, *polyline.interp(self.lists[0], self.lists[1:], s))

    def closest(self, px: float, py: float, hint: float | None, window: float) -> Row:
        """The row nearest ``(px, py)`` in ``[hint − window, hint + window]`` (None: all)."""
        key = (px, py, None if hint is None else float(hint), float(window))
        if (known := self.memo.get(key)) is not None:
            return known
        sl = self.lists[0]
        n = len(sl)
        first, last = 0, n - 1  # the segments first..last - 1 (mod n - 1 on a closed path)
        if hint is not None:
            h = self.wrap(hint)
            lo, hi = (polyline.search(sl, v) for v in (h - window, h + window))
            first, last = (lo - 1, hi + 1) if self.closed else (max(lo - 1, 0), min(hi + 1, n - 1))
        k, t = self.finder.nearest(first, last, px, py)
        i = (first + k) % (n - 1)
        row = self.at(sl[i] + float(t[k]) * (sl[i + 1] - sl[i]))
        if len(self.memo) >= MEMO:
            self.memo.clear()
        self.memo[key] = row
        return row

    def lookahead(self, px: float, py: float, distance: float, hint: float | None,
                  window: float) -> Row:
        """The row of the first sample ahead of the nearest point at ``distance`` or more.

        The samples ahead are ``s₀ + j h/4`` (``h`` the first sample spacing) up to
        ``2 distance + 4h`` beyond the nearest point ``s₀`` (an open path: to its end; none
        left: its end). Skipped unmeasured: the samples with ``|q(s₀) − p| + ρ (s − s₀)``
        below ``distance`` (minus the slack), which are inside the circle.
        """
        s0, qx, qy, _, _ = self.closest(px, py, hint, window)
        step = self.s[1]
        ahead = s0 + np.arange(0.0, (2.0 * distance + 4.0 * step), step / 4.0)
        if not self.closed:
            ahead = ahead[ahead <= self.length]
            if len(ahead) == 0:
                return self.at(self.length)
        if self._reach is None:
            self._reach = polyline.reach(self.seg, self.s, self.closed)
        (rho, slack), wraps = self._reach, self.closed and ahead[-1] - s0 > self.length
        lim = (distance - math.hypot(qx - px, qy - py) - slack) / rho
        j = int(ahead.searchsorted(s0 + lim)) if math.isfinite(lim) and not wraps else 0

        def far(a: np.ndarray) -> np.ndarray:  # np.linalg.norm(positions(a) − p, axis=1)
            w = self.wrap_array(a)
            dx = np.interp(w, self.s, self.seg.x)
            dx -= px
            dx *= dx
            dy = np.interp(w, self.s, self.seg.y)
            dy -= py
            dy *= dy
            dx += dy
            return np.sqrt(dx, out=dx)
        return self.at(ahead[polyline.first_beyond(far, ahead, j, distance)])
