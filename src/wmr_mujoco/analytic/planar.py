"""Planar geometry shared by the analytic models and the measurements.

Headings are angles about the world ``z`` axis; a path is a polyline of ``(x, y)`` points.
"""

from __future__ import annotations

import math

import numpy as np


def wrap_angle(angle: float | np.ndarray) -> float | np.ndarray:
    """Angle(s) wrapped into ``(-π, π]``: ``arg(exp(i·angle))``.

    A Python float takes ``math.remainder(angle, 2π)`` (exact; ``-π`` sent to ``π``):
    the same angle without numpy's per-call cost (control loops wrap one angle a step).
    """
    if type(angle) is float:
        wrapped = math.remainder(angle, math.tau)
        return math.pi if wrapped == -math.pi else wrapped
    wrapped = np.angle(np.exp(1j * np.asarray(angle, float)))
    return float(wrapped) if np.ndim(wrapped) == 0 else wrapped


def path_length(xy: np.ndarray) -> float:
    """Length of the polyline through the rows of ``xy`` (N, 2): ``Σ |p_{k+1} − p_k|``."""
    return float(cumulative_path(xy)[-1])


def cumulative_path(xy: np.ndarray) -> np.ndarray:
    """Path length from the first point to each point of the polyline (N,), 0 first."""
    xy = np.asarray(xy, float)
    steps = np.linalg.norm(np.diff(xy, axis=0), axis=1)
    return np.concatenate([[0.0], np.cumsum(steps)])


def yaw_from_rotation(xmat: np.ndarray) -> float:
    """Heading ``ψ = atan2(R₁₀, R₀₀)`` of a rotation matrix (3×3, or MuJoCo's flat 9).

    For ``R = R_z(ψ) R_y(θ) R_x(φ)`` the first column is
    ``(cos ψ cos θ, sin ψ cos θ, −sin θ)``, so the ratio gives ψ for any ``|θ| < π/2``.
    """
    m = np.asarray(xmat, float)
    if m.shape == (9,):  # MuJoCo's flat rows: R₁₀ and R₀₀ at 3 and 0
        return float(np.arctan2(m[3], m[0]))
    m = m.reshape(3, 3)
    return float(np.arctan2(m[1, 0], m[0, 0]))


def twist_step(pose: np.ndarray, twist: np.ndarray, dt: float) -> np.ndarray:
    """Exact pose after ``dt`` of a constant body twist: the exponential map of SE(2).

    With ``θ = r Δt`` the body moves on a circular arc; in its starting frame by::

        Δ = [[sin θ/θ, −(1 − cos θ)/θ], [(1 − cos θ)/θ, sin θ/θ]] (u, v) Δt

    so ``(x, y)⁺ = (x, y) + Rot(ψ) Δ`` and ``ψ⁺ = ψ + θ`` (the matrix → identity as
    θ → 0; a series is used below |θ| = 1e-4, error O(θ⁴)). It is what RK4 approximates
    for the kinematic model ``(Ẋ, Ẏ, ψ̇) = (Rot(ψ)(u, v), r)`` under a held input.

    Args:
        pose: ``(x, y, ψ)``.
        twist: ``(u, v, r)`` in the body frame.
        dt: s.
    """
    x, y, psi = pose[0], pose[1], pose[2]
    u, v, r = twist[0], twist[1], twist[2]
    th = r * dt
    if abs(th) < 1e-4:
        a, b = 1.0 - th * th / 6.0, th / 2.0 - th ** 3 / 24.0
    else:
        a, b = math.sin(th) / th, (1.0 - math.cos(th)) / th
    dx, dy = (a * u - b * v) * dt, (b * u + a * v) * dt
    c, s = math.cos(psi), math.sin(psi)
    return np.array([x + c * dx - s * dy, y + s * dx + c * dy, psi + th])


def twist_steps(pose: np.ndarray, twists: np.ndarray, dt: float) -> np.ndarray:
    """Poses after each of ``len(twists)`` steps of :func:`twist_step`, computed at once.

    The same floats as calling :func:`twist_step` step after step: every term is the
    same arithmetic elementwise, and each running sum (``ψ + θ``, then
    ``(x + c Δx) − s Δy`` and ``(y + s Δx) + c Δy`` in that order) is one sequential
    ``np.cumsum`` over the terms interleaved as they are added.

    Args:
        pose: ``(x, y, ψ)`` at the start.
        twists: (N, 3) body twists ``(u, v, r)``, each held over one step.
        dt: s.

    Returns:
        (N + 1, 3) poses, the start first.
    """
    w = np.asarray(twists, float).reshape(-1, 3)
    n = len(w)
    u, v, th = w[:, 0], w[:, 1], w[:, 2] * dt
    small = np.abs(th) < 1e-4
    safe = np.where(small, 1.0, th)
    a = np.where(small, 1.0 - th * th / 6.0, np.sin(safe) / safe)
    b = np.where(small, th / 2.0 - th ** 3 / 24.0, (1.0 - np.cos(safe)) / safe)
    dx, dy = (a * u - b * v) * dt, (b * u + a * v) * dt
    out = np.empty((n + 1, 3))
    out[:, 2] = np.cumsum(np.concatenate([[float(pose[2])], th]))
    c, s = np.cos(out[:-1, 2]), np.sin(out[:-1, 2])
    for j, (first, second) in enumerate(((c * dx, -(s * dy)), (s * dx, c * dy))):
        terms = np.empty(2 * n + 1)
        terms[0] = float(pose[j])
        terms[1::2], terms[2::2] = first, second
        out[:, j] = np.cumsum(terms)[::2]
    return out
