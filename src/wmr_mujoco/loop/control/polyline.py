"""A point's nearest foot on the segments of a polyline, column by column, and other queries.

For segments ``a → b = a + d`` the foot of a point ``p`` on each is ``a + t d`` with

    t = clip((p − a)·d / d·d, 0, 1),

and the nearest foot is the one of least ``|a + t d − p|²``. :func:`segments` keeps the
polyline's coordinates as contiguous columns and each segment's ``d`` and ``d·d`` once;
:func:`nearest` computes a window of segments' feet from them (:func:`feet`, in place;
:class:`Finder` keeps a point's for its next window). Each dot product is
``(0 + x₀y₀) + x₁y₁``, the order in which ``np.einsum("ij,ij->i", …)`` accumulates it, so
the feet are those of the row-wise einsum on the ``(N, 2)`` rows, at a fraction of its
cost (``tests/loop/control/test_polyline.py``).

Also: :func:`walk`, a local minimum of the distance found by walking from a segment;
:func:`interp`, ``np.interp`` of one point on Python lists, to the bit; :func:`reach`,
how far a point moves along the polyline per unit arc length (a bound that lets
:func:`first_beyond` skip the points surely closer than a distance).
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Callable
from typing import NamedTuple

import numpy as np

#: Points :func:`first_beyond` measures at once; segments :class:`Finder` measures beyond
#: each side of a window.
CHUNK, MARGIN = 128, 64


class Segments(NamedTuple):
    """A polyline's columns ``x``, ``y`` (N,) and per segment ``dx``, ``dy``, ``d·d`` (N − 1,)."""

    x: np.ndarray
    y: np.ndarray
    dx: np.ndarray
    dy: np.ndarray
    dd: np.ndarray


def segments(xy: np.ndarray) -> Segments:
    """The :class:`Segments` of the ``(N, 2)`` points ``xy``."""
    x, y = np.ascontiguousarray(xy[:, 0], float), np.ascontiguousarray(xy[:, 1], float)
    dx, dy = x[1:] - x[:-1], y[1:] - y[:-1]
    return Segments(x, y, dx, dy, 0.0 + dx * dx + dy * dy)


def nearest(seg: Segments, window: slice | np.ndarray, px: float, py: float
            ) -> tuple[int, np.ndarray]:
    """``(k, t)``: the window's segment ``k`` whose foot is nearest ``(px, py)``, every ``t``.

    ``window`` picks segments (a slice, or indices for a window that wraps round a
    closed polyline's end); ``k`` counts within it (the first of equal distances).
    """
    d, t = feet(seg, window, px, py)
    return int(d.argmin()), t


def feet(seg: Segments, window: slice | np.ndarray, px: float, py: float
         ) -> tuple[np.ndarray, np.ndarray]:
    """``(|a + t d − p|², t)`` of every segment of ``window`` (see :func:`nearest`).

    Computed in place, in the order of ``0.0 + (p − a)·d`` and ``0.0 + |a + t d − p|²``
    (``0.0 +`` changes only a −0, which a square never is); ``np.clip``'s ``t`` as
    ``np.minimum(np.maximum(·))`` (a quotient of a sum starting ``0.0 +`` is never −0).
    """
    ax, ay, sx, sy = seg.x[window], seg.y[window], seg.dx[window], seg.dy[window]
    t = np.subtract(px, ax)
    t *= sx
    t += 0.0
    u = np.subtract(py, ay)
    u *= sy
    t += u
    t /= seg.dd[window]
    np.maximum(t, 0.0, out=t)
    np.minimum(t, 1.0, out=t)
    d = np.multiply(t, sx)
    d += ax
    d -= px
    d *= d
    np.multiply(t, sy, out=u)
    u += ay
    u -= py
    u *= u
    d += u
    return d, t


class Finder:
    """:func:`nearest` on windows of segments, keeping a point's feet for its next window.

    A control loop asks twice for one point with windows a step apart (pure pursuit: its
    closest point, then its lookahead's): the feet are measured on the window and
    :data:`MARGIN` segments each side, and a later window of the same point inside
    those is answered from them (the same floats: each foot is its segment's alone).

    Args:
        seg: the polyline's segments.
    """

    def __init__(self, seg: Segments) -> None:
        self.seg = seg
        self._kept: tuple[float, float, int, int, np.ndarray, np.ndarray] | None = None

    def nearest(self, first: int, last: int, px: float, py: float) -> tuple[int, np.ndarray]:
        """:func:`nearest` on the segments ``first .. last − 1`` (mod their number)."""
        n = len(self.seg.dd)
        if first < 0 or last > n:  # a window round a closed polyline's end
            return nearest(self.seg, np.mod(np.arange(first, last), n), px, py)
        kept = self._kept
        if (kept is None or kept[0] != px or kept[1] != py
                or not kept[2] <= first <= last <= kept[3]):
            lo, hi = max(first - MARGIN, 0), min(last + MARGIN, n)
            kept = self._kept = (px, py, lo, hi, *feet(self.seg, slice(lo, hi), px, py))
        lo = kept[2]
        t = kept[5][first - lo:last - lo]
        return int(kept[4][first - lo:last - lo].argmin()), t


def search(xp: list[float], x: float) -> int:
    """``np.searchsorted(xp, x)`` (side left, NaN after everything) on a list."""
    return bisect.bisect_left(xp, x) if x == x else len(xp)


def interp(xp: list[float], columns: tuple[list[float], ...], x: float) -> tuple[float, ...]:
    """``np.interp(x, xp, c)`` of every column ``c`` at one ``x``, on Python floats.

    ``j`` the last index with ``xp[j] <= x`` (``xp`` increasing), the value is numpy's

        c[0] before xp[0];  c[j] at a sample or at and after xp[-1];
        (c[j+1] − c[j]) / (xp[j+1] − xp[j]) · (x − xp[j]) + c[j]  between,

    in its order of operations (and its fallbacks when that is NaN), so the same floats
    (``tests/loop/control/test_polyline.py``) without a numpy call per column.
    """
    if x != x:
        return (x,) * len(columns)
    j = bisect.bisect_right(xp, x) - 1
    if j < 0:
        return tuple(c[0] for c in columns)
    if j >= len(xp) - 1 or xp[j] == x:
        return tuple(c[j] for c in columns)
    x0, x1 = xp[j], xp[j + 1]
    out = []
    for c in columns:
        y0, y1 = c[j], c[j + 1]
        slope = (y1 - y0) / (x1 - x0)
        y = slope * (x - x0) + y0
        if y != y:
            y = slope * (x - x1) + y1
            if y != y and y0 == y1:
                y = y0
        out.append(y)
    return tuple(out)


def walk(s: list[float], xy: list[list[float]], closed: bool, px: float, py: float,
         hint: float) -> tuple[int, float]:
    """``(i, t)``: the foot on segment ``i`` of a local minimum of the distance to ``(px, py)``.

    From the segment at arc length ``hint`` (``s`` the points' arc lengths, ``xy`` their
    rows) it walks along the polyline while the distance shrinks (round the end of a
    closed one).
    """
    n = len(s) - 1

    def foot(i: int) -> tuple[float, float]:
        (ax, ay), (bx, by) = xy[i % n], xy[i % n + 1]
        dx, dy = bx - ax, by - ay
        t = min(1.0, max(0.0, ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)))
        return (ax + t * dx - px) ** 2 + (ay + t * dy - py) ** 2, t

    i = max(0, min(bisect.bisect_right(s, hint % s[-1] if closed else hint) - 1, n - 1))
    best, t = foot(i)
    for step in (1, -1):
        while closed or 0 <= i + step < n:
            d, u = foot(i + step)
            if d >= best:
                break
            i, best, t = i + step, d, u
    return i % n, t


def reach(seg: Segments, s: np.ndarray, closed: bool) -> tuple[float, float]:
    """``(ρ, slack)``: the most length per unit ``s`` of the segments, and a bound's slack, m.

    The polyline parameterised by ``s`` (linear on each segment) moves at most ``ρ`` per
    unit ``s``: ``|q(s₁) − q(s₀)| ≤ ρ |s₁ − s₀|`` (``ρ`` inf where ``s`` stalls), plus,
    round a closed one's end, the gap between its ends; ``slack`` adds that gap to
    ``1e-9 (1 + max |coordinate| + length)`` m, far above the floats' rounding.
    """
    ds = np.diff(s)
    rho = math.inf
    if len(ds) and np.all(ds > 0):
        rho = float(np.max(np.sqrt(seg.dd) / ds)) * (1.0 + 1e-9)
    size = max(float(np.abs(seg.x).max()), float(np.abs(seg.y).max())) if len(s) else 0.0
    gap = math.hypot(seg.x[-1] - seg.x[0], seg.y[-1] - seg.y[0]) if closed and len(s) else 0.0
    slack = 1e-9 * (1.0 + size + float(s[-1] if len(s) else 0.0)) + gap
    return (rho if math.isfinite(rho) else math.inf), slack


def first_beyond(distances: Callable[[np.ndarray], np.ndarray], ahead: np.ndarray,
                 start: int, distance: float) -> int:
    """The first ``j >= start`` with ``distances(ahead)[j] >= distance`` (-1: none).

    ``distances`` maps arc lengths to the distances of their points (each its own, whatever
    the others); :data:`CHUNK` of them are measured at a time.
    """
    for j in range(start, len(ahead), CHUNK):
        far = (distances(ahead[j:j + CHUNK]) >= distance).nonzero()[0]
        if len(far):
            return j + int(far[0])
    return -1
