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
LEFT of the path. These point queries run on Python floats, with the floats of these array
formulas (:mod:`~wmr_mujoco.loop.control.path_index`).

Paths: :func:`line`, :func:`circle`, :func:`figure_eight`, :func:`lane_change` and
:func:`random_spline` (seeded); :func:`make_path` builds one by name (:data:`PATHS`).
The learning tasks (:mod:`wmr_mujoco.envs`) draw :func:`random_path` (bounded curvature)
and plan with :func:`hermite_path` (pose to pose); :func:`extend` runs a path on straight.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy.interpolate import CubicSpline

from wmr_mujoco.loop.control import polyline
from wmr_mujoco.loop.control.path_index import PathIndex

#: Fine samples per path.
SAMPLES = 4001
#: Half-width of the closest-point search around a hint, m.
HINT_WINDOW = 1.0
#: Sample spacing of the random and Hermite paths, m.
DS = 0.02


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

    def at(self, s: float) -> PathPoint:
        """The point at arc length ``s`` (wrapped on a closed path, clipped on an open one)."""
        return _point(self._index.at(s))

    def closest(self, point: np.ndarray, hint: float | None = None,
                window: float = HINT_WINDOW) -> PathPoint:
        """The path's point nearest ``point`` (projection onto the polyline).

        Args:
            point: ``(x, y)`` (a longer array's first two entries are used).
            hint: arc length of the previous answer; the search is limited to
                ``[hint − window, hint + window]`` (wrapped on a closed path). None: the
                whole path.
            window: half-width of that search, m.

        Answers are kept (:data:`~wmr_mujoco.loop.control.path_index.MEMO`): a loop's
        cross-track pass asks its controller's again.
        """
        p = np.asarray(point, float)[:2]
        return _point(self._index.closest(float(p[0]), float(p[1]), hint, window))

    #: The samples kept for the point queries (:mod:`~wmr_mujoco.loop.control.path_index`).
    _index = cached_property(lambda self: PathIndex(self.s, self.xy, self.heading,
                                                    self.curvature, self.closed))

    _rows = cached_property(lambda self: (self.s.tolist(), self.xy.tolist()))

    def track(self, point: np.ndarray, hint: float) -> PathPoint:
        """:meth:`closest` for a point that moved little since the answer at ``hint``, m.

        From the segment at ``hint`` it walks along the path while the distance shrinks:
        for a control loop, once a step, at a fraction of :meth:`closest`'s cost.
        """
        i, t = polyline.walk(*self._rows, self.closed, float(point[0]), float(point[1]), hint)
        f = lambda a: float(a[i] + t * (a[i + 1] - a[i]))  # noqa: E731 - linear in s
        return PathPoint(f(self.s), self.xy[i] + t * (self.xy[i + 1] - self.xy[i]),
                         f(self.heading), f(self.curvature))

    def cross_track(self, point: np.ndarray, hint: float | None = None) -> tuple[float, float]:
        """Signed cross-track error (> 0: ``point`` left of the path), m, and its arc length.

        Off the end of an open path the distance to the end point is returned, signed by
        the side.
        """
        p = np.asarray(point, float)[:2]
        rx, ry = float(p[0]), float(p[1])
        s, qx, qy, heading, _ = self._index.closest(rx, ry, hint, HINT_WINDOW)
        rx, ry = rx - qx, ry - qy
        side = -np.sin(heading) * rx + np.cos(heading) * ry
        return math.copysign(float(np.hypot(rx, ry)), side), s

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
        return _point(self._index.lookahead(float(p[0]), float(p[1]), distance, hint,
                                            HINT_WINDOW))

    def positions(self, s: np.ndarray) -> np.ndarray:
        """``(x, y)`` at the arc lengths ``s`` (wrapped or clipped like :meth:`at`), (..., 2)."""
        s = self._index.wrap_array(np.asarray(s, float))
        out = np.empty((*s.shape, 2))
        out[..., 0] = np.interp(s, self.s, self._index.seg.x)
        out[..., 1] = np.interp(s, self.s, self._index.seg.y)
        return out


def _point(row: tuple[float, float, float, float, float]) -> PathPoint:
    """The :class:`PathPoint` of a row ``(s, x, y, heading, curvature)``."""
    return PathPoint(row[0], np.array(row[1:3]), row[3], row[4])


Curve = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]


def from_curve(name: str, curve: Curve, tau_end: float, closed: bool = False,
               samples: int = SAMPLES) -> Path:
    """Sample ``curve(τ) -> (p, p', p'')`` (each ``(N, 2)``) ``samples`` times on ``[0, τ_end]``."""
    tau = np.linspace(0.0, tau_end, samples)
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


def extend(path: Path, run_out: float, ds: float = DS) -> Path:
    """An open ``path`` continued straight along its end heading for ``run_out`` m."""
    n = math.ceil(run_out / ds)
    if path.closed or n <= 0:
        return path
    extra, psi = ds * np.arange(1, n + 1), float(path.heading[-1])
    xy = path.xy[-1] + extra[:, None] * np.array([math.cos(psi), math.sin(psi)])
    return Path(path.name, np.concatenate([path.s, path.s[-1] + extra]),
                np.concatenate([path.xy, xy]), np.concatenate([path.heading, np.full(n, psi)]),
                np.concatenate([path.curvature, np.zeros(n)]))


def random_path(rng: np.random.Generator, start: np.ndarray, length: float,
                max_curvature: float, modes: int = 3, ds: float = DS) -> Path:
    """A random smooth path of ``length`` m from the pose ``start``, ``|κ| ≤ max_curvature``.

    The curvature is a random band-limited sum, ramped up from 0 over the first 10 %,

        κ(s) = min(1, s / 0.1ℓ) Σ_k a_k sin(2π s / λ_k + φ_k),   Σ |a_k| ≤ κ_max,

    and the path its integral, ``ψ(s) = ψ₀ + ∫κ``, ``(x, y)(s) = ∫(cos ψ, sin ψ)``
    (trapezoids of ``ds``: the path is C² and never turns tighter than ``1/κ_max``).
    Amplitudes: Dirichlet weights times ``κ_max U(0.5, 1)``; wavelengths ``U(0.5, 1.5) ℓ``.

    Raises:
        ValueError: a non-positive length or curvature, or no modes.
    """
    if not (length > 0 and max_curvature > 0 and modes >= 1):
        raise ValueError(f"length={length!r} m, max_curvature={max_curvature!r} 1/m and "
                         f"modes={modes!r} must all be positive")
    s = np.linspace(0.0, length, math.ceil(length / ds) + 1)
    amp = rng.dirichlet(np.ones(modes)) * max_curvature * rng.uniform(0.5, 1.0)
    lam, phi = rng.uniform(0.5, 1.5, modes) * length, rng.uniform(0.0, 2 * math.pi, modes)
    amp *= rng.choice([-1.0, 1.0], modes)
    kappa = (amp * np.sin(2 * math.pi * s[:, None] / lam + phi)).sum(1)
    kappa *= np.clip(s / (0.1 * length), 0.0, 1.0)
    h = np.diff(s)
    heading = start[2] + np.concatenate([[0.0], np.cumsum(0.5 * (kappa[1:] + kappa[:-1]) * h)])
    step = np.stack([np.cos(heading), np.sin(heading)], axis=1)
    xy = np.asarray(start[:2], float) + np.concatenate(
        [[[0.0, 0.0]], np.cumsum(0.5 * (step[1:] + step[:-1]) * h[:, None], axis=0)])
    return Path("random_path", s, xy, heading, kappa)


def hermite_path(start: np.ndarray, goal: np.ndarray, tangent: float = 1.0,
                 ds: float = DS) -> Path:
    """The cubic Hermite curve from the pose ``start`` to the pose ``goal``.

    ``p(τ) = h₀₀ p₀ + h₁₀ m₀ + h₀₁ p₁ + h₁₁ m₁``, ``τ ∈ [0, 1]``, with tangents
    ``m = k d (cos ψ, sin ψ)``, ``d = |p₁ − p₀|``, ``k = tangent``; 2d/ds samples (>= 64).
    """
    p0, p1 = np.asarray(start[:2], float), np.asarray(goal[:2], float)
    d = float(np.hypot(*(p1 - p0)))
    m0, m1 = (tangent * d * np.array([math.cos(q[2]), math.sin(q[2])]) for q in (start, goal))

    def curve(t: np.ndarray):  # the basis h₀₀, h₁₀, h₀₁, h₁₁ and its two derivatives
        t = t[:, None]
        return tuple(a * p0 + b * m0 + c * p1 + e * m1 for a, b, c, e in (
            (2 * t**3 - 3 * t**2 + 1, t**3 - 2 * t**2 + t, 3 * t**2 - 2 * t**3, t**3 - t**2),
            (6 * t**2 - 6 * t, 3 * t**2 - 4 * t + 1, 6 * t - 6 * t**2, 3 * t**2 - 2 * t),
            (12 * t - 6, 6 * t - 4, 6 - 12 * t, 6 * t - 2)))
    return from_curve("hermite_path", curve, 1.0, samples=max(64, math.ceil(2 * d / ds)))


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
