"""Smooth planar reference paths for the learning tasks: random, seeded, and goal-reaching.

A :class:`Path` is a polyline sampled every ``ds`` metres of arc length, with its heading
``ψ(s)``. :func:`random_path` integrates a random, band-limited curvature,

    κ(s) = Σ_k a_k sin(2π s / λ_k + φ_k),   ψ(s) = ψ₀ + ∫ κ,   (x, y)(s) = ∫ (cos ψ, sin ψ),

with ``Σ |a_k| ≤ κ_max``, so the path is C² and never turns tighter than ``1 / κ_max``.
:func:`hermite_path` joins two poses by a cubic Hermite curve (tangent lengths ``k d``),
then runs straight on past the end pose, so a follower converges onto the end pose's line.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.analytic.planar import wrap_angle

#: Arc-length spacing of the polyline, m.
DS = 0.02


@dataclass(frozen=True)
class Projection:
    """A point's nearest place on the path.

    Attributes:
        index: polyline index of the nearest vertex.
        s: arc length there, m.
        cross_track: signed distance, m (> 0: the point is left of the path).
        heading: path heading there, rad.
    """

    index: int
    s: float
    cross_track: float
    heading: float


@dataclass(frozen=True, eq=False)
class Path:
    """A polyline with arc length and heading.

    Attributes:
        points: (N, 2) vertices, m.
        heading: (N,) path heading at each vertex, rad.
        s: (N,) arc length at each vertex, m.
        end_index: index of the path's end proper (vertices beyond it run on straight).
    """

    points: np.ndarray
    heading: np.ndarray
    s: np.ndarray
    end_index: int

    @property
    def length(self) -> float:
        """Arc length to the end proper, m."""
        return float(self.s[self.end_index])

    @property
    def end_pose(self) -> np.ndarray:
        """``(x, y, ψ)`` at the end proper."""
        i = self.end_index
        return np.array([*self.points[i], self.heading[i]])

    def project(self, xy: np.ndarray, hint: int | None = None, window: int = 200
                ) -> Projection:
        """Nearest vertex to ``xy`` (searched around ``hint`` if given, else everywhere)."""
        lo, hi = (0, len(self.s)) if hint is None else (
            max(0, hint - window // 4), min(len(self.s), hint + window))
        d = self.points[lo:hi] - xy
        i = lo + int(np.argmin(np.einsum("ij,ij->i", d, d)))
        c, s = math.cos(self.heading[i]), math.sin(self.heading[i])
        rx, ry = xy - self.points[i]
        return Projection(i, float(self.s[i]), -s * rx + c * ry, float(self.heading[i]))

    def ahead(self, index: int, distances: np.ndarray) -> np.ndarray:
        """Points at arc lengths ``s[index] + distances`` (clamped to the polyline), (K, 2)."""
        target = self.s[index] + np.asarray(distances)
        j = np.clip(np.searchsorted(self.s, target), 0, len(self.s) - 1)
        return self.points[j]


def _integrate(start: np.ndarray, kappa: np.ndarray, ds: float) -> tuple[np.ndarray, ...]:
    heading = start[2] + np.concatenate([[0.0], np.cumsum(0.5 * (kappa[1:] + kappa[:-1]) * ds)])
    step = np.stack([np.cos(heading), np.sin(heading)], axis=1) * ds
    pts = start[:2] + np.concatenate([[[0.0, 0.0]], np.cumsum(0.5 * (step[1:] + step[:-1]),
                                                              axis=0)])
    return pts, heading


def random_path(rng: np.random.Generator, start: np.ndarray, length: float,
                max_curvature: float, modes: int = 3, run_out: float = 1.0,
                ds: float = DS) -> Path:
    """A random smooth path of ``length`` m from the pose ``start``, plus ``run_out`` m straight.

    Args:
        rng: the episode's random generator.
        start: ``(x, y, ψ)`` where the path begins, m, m, rad.
        length: arc length, m (> 0).
        max_curvature: bound on ``|κ|``, 1/m (> 0).
        modes: sinusoids summed in κ(s).
        run_out: straight continuation beyond the end, m.
        ds: vertex spacing, m.

    Raises:
        ValueError: a non-positive length, curvature or mode count.
    """
    if not (length > 0 and max_curvature > 0 and modes >= 1):
        raise ValueError(f"length={length!r} m, max_curvature={max_curvature!r} 1/m and "
                         f"modes={modes!r} must all be positive")
    n = math.ceil(length / ds) + 1
    s = np.linspace(0.0, length, n)
    weights = rng.dirichlet(np.ones(modes)) * max_curvature * rng.uniform(0.5, 1.0)
    wavelengths = rng.uniform(0.5, 1.5, modes) * length
    phases = rng.uniform(0.0, 2 * math.pi, modes)
    signs = rng.choice([-1.0, 1.0], modes)
    kappa = (signs * weights * np.sin(2 * math.pi * s[:, None] / wavelengths + phases)).sum(1)
    kappa *= np.clip(s / (0.1 * length), 0.0, 1.0)  # start straight: κ(0) = 0
    return _with_run_out(*_integrate(np.asarray(start, float), kappa, ds), ds, run_out)


def hermite_path(start: np.ndarray, goal: np.ndarray, tangent: float = 1.0,
                 run_out: float = 1.0, ds: float = DS) -> Path:
    """Cubic Hermite curve from pose ``start`` to pose ``goal``, then ``run_out`` m straight.

    ``p(t) = h₀₀ p₀ + h₁₀ m₀ + h₀₁ p₁ + h₁₁ m₁`` with tangents ``m = k d (cos ψ, sin ψ)``,
    ``d = |p₁ − p₀|``, ``k = tangent``; resampled to arc-length spacing ``ds``.
    """
    p0, p1 = np.asarray(start[:2], float), np.asarray(goal[:2], float)
    d = float(np.linalg.norm(p1 - p0))
    m0 = tangent * d * np.array([math.cos(start[2]), math.sin(start[2])])
    m1 = tangent * d * np.array([math.cos(goal[2]), math.sin(goal[2])])
    t = np.linspace(0.0, 1.0, max(64, math.ceil(4 * d / ds)))[:, None]
    h00, h10 = 2 * t**3 - 3 * t**2 + 1, t**3 - 2 * t**2 + t
    h01, h11 = -2 * t**3 + 3 * t**2, t**3 - t**2
    dense = h00 * p0 + h10 * m0 + h01 * p1 + h11 * m1
    seg = np.linalg.norm(np.diff(dense, axis=0), axis=1)
    s_dense = np.concatenate([[0.0], np.cumsum(seg)])
    s = np.linspace(0.0, s_dense[-1], max(2, math.ceil(s_dense[-1] / ds) + 1))
    pts = np.stack([np.interp(s, s_dense, dense[:, 0]), np.interp(s, s_dense, dense[:, 1])], 1)
    diff = np.gradient(pts, axis=0)
    heading = np.unwrap(np.arctan2(diff[:, 1], diff[:, 0]))
    heading[0], heading[-1] = start[2], heading[-1] + _wrap(goal[2] - heading[-1])
    return _with_run_out(pts, heading, ds, run_out)


def _wrap(a: float) -> float:
    return float(wrap_angle(a))


def _with_run_out(pts: np.ndarray, heading: np.ndarray, ds: float, run_out: float) -> Path:
    n_out = max(0, math.ceil(run_out / ds))
    end = len(pts) - 1
    out = ds * np.arange(1, n_out + 1)[:, None] * np.array(
        [math.cos(heading[-1]), math.sin(heading[-1])])
    pts = np.concatenate([pts, pts[-1] + out])
    heading = np.concatenate([heading, np.full(n_out, heading[-1])])
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(pts, axis=0), axis=1))])
    return Path(pts, heading, s, end)
