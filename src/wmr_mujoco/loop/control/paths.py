"""Reference paths in the plane, parameterised by arc length.

A path is a smooth curve ``p(τ) = (x(τ), y(τ))`` given with its first two derivatives.
It is sampled densely (:data:`SAMPLES` points) and every quantity is stored against the
arc length ``s``:

    s(τ) = ∫ |p'(τ)| dτ                      (trapezoid on the fine grid, error O(h²))
    ψ(τ) = atan2(y', x')                     (heading, unwrapped)
    κ(τ) = (x' y'' − y' x'') / |p'|³         (signed curvature, > 0 turning left)

Queries between samples interpolate linearly (position error ``≤ κ h² / 8`` for a sample
spacing ``h``: under 10 µm for the paths here). The closest-point query projects onto
the polyline's segments; given the previous arc length as a hint it searches only a
window around it, so that a path crossing itself (the figure eight) is followed along,
not jumped across. The cross-track error is signed, positive when the point lies to the
LEFT of the path.

Paths: :func:`line`, :func:`circle`, :func:`figure_eight`, :func:`lane_change` and
:func:`random_spline` (seeded); :func:`make_path` builds one by name (:data:`PATHS`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import CubicSpline

#: Fine samples per path.
SAMPLES = 4001
#: Half-width of the closest-point search around a hint, m.
HINT_WINDOW = 1.0


@dataclass(frozen=True)
class PathPoint:
    """One point of a path.

    Attributes:
        s: arc length from the start, m.
        position: ``(x, y)``, m.
        heading: tangent direction, rad (unwrapped along the path).
        curvature: signed curvature, 1/m (> 0: turning left).
    """

    s: float
    position: np.ndarray
    heading: float
    curvature: float

    @property
    def pose(self) -> np.ndarray:
        """``(x, y, heading)``."""
        return np.array([self.position[0], self.position[1], self.heading])


@dataclass(frozen=True)
class Path:
    """A planar path sampled against arc length (module docstring).

    Attributes:
        name: what it is, for tables.
        s: ``(N,)`` arc lengths, increasing from 0, m.
        xy: ``(N, 2)`` positions, m.
        heading: ``(N,)`` unwrapped tangent headings, rad.
        curvature: ``(N,)`` signed curvatures, 1/m.
        closed: whether the end joins the start (arc lengths wrap).
    """

    name: str
    s: np.ndarray
    xy: np.ndarray
    heading: np.ndarray
    curvature: np.ndarray
    closed: bool = False

    @property
    def length(self) -> float:
        """Total arc length, m."""
        return float(self.s[-1])

    @property
    def start_pose(self) -> np.ndarray:
        """``(x, y, heading)`` at ``s = 0``."""
        return self.at(0.0).pose

    def _s(self, s: float) -> float:
        if self.closed:
            return float(np.mod(s, self.length))
        return float(np.clip(s, 0.0, self.length))

    def at(self, s: float) -> PathPoint:
        """The point at arc length ``s`` (wrapped on a closed path, clipped on an open one)."""
        s = self._s(s)
        xy = np.array([np.interp(s, self.s, self.xy[:, 0]), np.interp(s, self.s, self.xy[:, 1])])
        return PathPoint(s, xy, float(np.interp(s, self.s, self.heading)),
                         float(np.interp(s, self.s, self.curvature)))

    def closest(self, point: np.ndarray, hint: float | None = None,
                window: float = HINT_WINDOW) -> PathPoint:
        """The path's point nearest ``point`` (projection onto the polyline).

        Args:
            point: ``(x, y)`` (a longer array's first two entries are used).
            hint: arc length of the previous answer; the search is limited to
                ``[hint − window, hint + window]`` (wrapped on a closed path). None: the
                whole path.
            window: half-width of that search, m.
        """
        p = np.asarray(point, float)[:2]
        n = len(self.s)
        if hint is None:
            idx = np.arange(n - 1)
        else:
            h = self._s(hint)
            lo, hi = np.searchsorted(self.s, [h - window, h + window])
            idx = np.arange(lo - 1, hi + 1)
            idx = np.mod(idx, n - 1) if self.closed else idx[(idx >= 0) & (idx < n - 1)]
        a, b = self.xy[idx], self.xy[idx + 1]
        d = b - a
        t = np.clip(np.einsum("ij,ij->i", p - a, d) / np.einsum("ij,ij->i", d, d), 0.0, 1.0)
        foot = a + t[:, None] * d
        k = int(np.argmin(np.einsum("ij,ij->i", foot - p, foot - p)))
        return self.at(self.s[idx[k]] + t[k] * (self.s[idx[k] + 1] - self.s[idx[k]]))

    def cross_track(self, point: np.ndarray, hint: float | None = None) -> tuple[float, float]:
        """Signed cross-track error (> 0: ``point`` left of the path), m, and its arc length.

        Off the end of an open path the distance to the end point is returned, signed by
        the side.
        """
        q = self.closest(point, hint)
        rel = np.asarray(point, float)[:2] - q.position
        side = -np.sin(q.heading) * rel[0] + np.cos(q.heading) * rel[1]
        return float(np.copysign(np.hypot(*rel), side)), q.s

    def lookahead(self, point: np.ndarray, distance: float, hint: float | None = None
                  ) -> PathPoint:
        """The first path point beyond the closest one at distance ``distance`` from ``point``.

        This is Coulter's goal point: on the path ahead, on the circle of radius
        ``distance`` around the vehicle. If the whole rest of an open path lies inside
        that circle, the end point is returned.

        Raises:
            ValueError: ``distance`` not a finite number > 0.
        """
        if not (np.isfinite(distance) and distance > 0):
            raise ValueError(f"distance = {distance!r}; must be a finite number > 0 m")
        p = np.asarray(point, float)[:2]
        s0 = self.closest(p, hint).s
        step = self.s[1]
        ahead = s0 + np.arange(0.0, (2.0 * distance + 4.0 * step), step / 4.0)
        if not self.closed:
            ahead = ahead[ahead <= self.length]
            if len(ahead) == 0:
                return self.at(self.length)
        pts = np.stack([np.interp(self._wrap(ahead), self.s, self.xy[:, i]) for i in (0, 1)], 1)
        beyond = np.flatnonzero(np.linalg.norm(pts - p, axis=1) >= distance)
        return self.at(ahead[beyond[0]] if len(beyond) else ahead[-1])

    def _wrap(self, s: np.ndarray) -> np.ndarray:
        return np.mod(s, self.length) if self.closed else np.clip(s, 0.0, self.length)


Curve = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]


def from_curve(name: str, curve: Curve, tau_end: float, closed: bool = False) -> Path:
    """Sample ``curve(τ) -> (p, p', p'')`` (each ``(N, 2)``) on ``[0, tau_end]``."""
    tau = np.linspace(0.0, tau_end, SAMPLES)
    p, dp, ddp = curve(tau)
    speed = np.linalg.norm(dp, axis=1)
    s = np.concatenate([[0.0], np.cumsum(0.5 * (speed[1:] + speed[:-1]) * np.diff(tau))])
    heading = np.unwrap(np.arctan2(dp[:, 1], dp[:, 0]))
    kappa = (dp[:, 0] * ddp[:, 1] - dp[:, 1] * ddp[:, 0]) / speed**3
    return Path(name, s, p, heading, kappa, closed)


def _positive(name: str, value: float) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)) \
            or not np.isfinite(value) or value <= 0:
        raise ValueError(f"{name} = {value!r}; must be a finite number > 0")
    return float(value)


def line(length: float = 10.0) -> Path:
    """Straight line from the origin along +x."""
    ell = _positive("length", length)
    one, zero = np.ones(SAMPLES), np.zeros(SAMPLES)
    return from_curve("line", lambda t: (np.stack([t, 0 * t], 1), np.stack([one, zero], 1),
                                         np.stack([zero, zero], 1)), ell)


def circle(radius: float = 2.0) -> Path:
    """Counter-clockwise circle through the origin, heading +x there, centre ``(0, R)``."""
    r = _positive("radius", radius)

    def curve(t: np.ndarray):
        c, s = np.cos(t), np.sin(t)
        return (np.stack([r * s, r * (1 - c)], 1), np.stack([r * c, r * s], 1),
                np.stack([-r * s, r * c], 1))
    return from_curve("circle", curve, 2 * np.pi, closed=True)


def figure_eight(size: float = 4.0) -> Path:
    """Lemniscate of Gerono ``(a sin τ, (a/2) sin 2τ)``, half-width ``a = size``."""
    a = _positive("size", size)

    def curve(t: np.ndarray):
        return (np.stack([a * np.sin(t), 0.5 * a * np.sin(2 * t)], 1),
                np.stack([a * np.cos(t), a * np.cos(2 * t)], 1),
                np.stack([-a * np.sin(t), -2 * a * np.sin(2 * t)], 1))
    return from_curve("figure_eight", curve, 2 * np.pi, closed=True)


def lane_change(offset: float = 1.0, transition: float = 5.0, straight: float = 3.0) -> Path:
    """Straight, a C²-smooth sideways shift by ``offset`` over ``transition`` m, straight.

    ``y = offset · S((x − straight) / transition)`` with the quintic smoothstep
    ``S(u) = 10u³ − 15u⁴ + 6u⁵`` on ``[0, 1]`` (0 before, 1 after): continuous curvature.
    """
    off, tr, st = offset, _positive("transition", transition), _positive("straight", straight)
    if not np.isfinite(off):
        raise ValueError(f"offset = {offset!r}; must be a finite number")

    def curve(x: np.ndarray):
        u = np.clip((x - st) / tr, 0.0, 1.0)
        y = off * (10 * u**3 - 15 * u**4 + 6 * u**5)
        dy = off * (30 * u**2 - 60 * u**3 + 30 * u**4) / tr
        ddy = off * (60 * u - 180 * u**2 + 120 * u**3) / tr**2
        one, zero = np.ones_like(x), np.zeros_like(x)
        return np.stack([x, y], 1), np.stack([one, dy], 1), np.stack([zero, ddy], 1)
    return from_curve("lane_change", curve, 2 * st + tr)


def random_spline(seed: int = 0, knots: int = 8, spacing: float = 2.0,
                  max_turn: float = 0.6) -> Path:
    """A smooth random path: a cubic spline through a seeded random walk of knots.

    Knot ``k + 1`` lies ``spacing`` m from knot ``k`` in a direction that turns by a
    uniform draw in ``[−max_turn, max_turn]`` rad; the first leg heads along +x from the
    origin. The spline (parameter: chord length, natural ends) is C².

    Raises:
        ValueError: a bad seed (not a non-negative integer) or size.
    """
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise ValueError(f"seed = {seed!r}; must be an integer >= 0")
    if isinstance(knots, bool) or not isinstance(knots, int) or not 3 <= knots <= 100:
        raise ValueError(f"knots = {knots!r}; must be an integer in [3, 100]")
    step = _positive("spacing", spacing)
    turn = _positive("max_turn", max_turn)
    rng = np.random.default_rng(seed)
    angles = np.concatenate([[0.0], np.cumsum(rng.uniform(-turn, turn, knots - 2))])
    pts = np.vstack([[0.0, 0.0], step * np.cumsum(np.stack([np.cos(angles),
                                                            np.sin(angles)], 1), 0)])
    chord = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(pts, axis=0), axis=1))])
    spline = CubicSpline(chord, pts, bc_type=((1, [1.0, 0.0]), "natural"))
    return from_curve(f"random_spline(seed={seed})",
                      lambda t: (spline(t), spline(t, 1), spline(t, 2)), float(chord[-1]))


#: The paths by name; each factory takes the seed (used only by the random spline).
PATHS: dict[str, Callable[[int], Path]] = {
    "line": lambda seed: line(),
    "circle": lambda seed: circle(),
    "figure_eight": lambda seed: figure_eight(),
    "lane_change": lambda seed: lane_change(),
    "random_spline": lambda seed: random_spline(seed),
}


def make_path(name: str, seed: int = 0) -> Path:
    """A path from :data:`PATHS` by name.

    Raises:
        ValueError: unknown name (the message lists the valid ones) or bad seed.
    """
    if name not in PATHS:
        raise ValueError(f"unknown path {name!r}; valid paths: {', '.join(PATHS)}")
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise ValueError(f"seed = {seed!r}; must be an integer >= 0")
    return PATHS[name](seed)
