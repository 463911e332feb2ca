"""A point's nearest foot on the segments of a polyline, column by column.

For segments ``a → b = a + d`` the foot of a point ``p`` on each is ``a + t d`` with

    t = clip((p − a)·d / d·d, 0, 1),

and the nearest foot is the one of least ``|a + t d − p|²``. :func:`segments` keeps the
polyline's coordinates as contiguous columns and each segment's ``d`` and ``d·d`` once;
:func:`nearest` computes a window of segments' feet from them. Each dot product is
``(0 + x₀y₀) + x₁y₁``, the order in which ``np.einsum("ij,ij->i", …)`` accumulates it, so
the feet are those of the row-wise einsum on the ``(N, 2)`` rows, at a fraction of its
cost (``tests/loop/control/test_polyline.py``).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np


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
    ax, ay, sx, sy = seg.x[window], seg.y[window], seg.dx[window], seg.dy[window]
    t = np.clip((0.0 + (px - ax) * sx + (py - ay) * sy) / seg.dd[window], 0.0, 1.0)
    ex, ey = ax + t * sx - px, ay + t * sy - py
    return int(np.argmin(0.0 + ex * ex + ey * ey)), t
