"""Non-holonomic rolling constraints in Pfaffian form ``A(q) q̇ = 0``.

Each row is a velocity of a wheel's contact point (m/s), so a residual is a slip speed.
Rows come in two kinds for every wheel: *lateral* (no velocity across the wheel plane, the
lecture's constraints) and *rolling* (ground speed along the wheel plane equals ``R θ̇``).

Coordinates:
    disc:     ``q = (x, y, φ, θ)``
    bicycle:  ``q = (x, y, ψ, φ, θ_r, θ_f)``, (x, y) the rear contact
    tricycle: ``q = (x, y, ψ, φ, θ_L, θ_R, θ_F)``, (x, y) the rear-axle midpoint

Rows (c = cos, s = sin):
    lateral of a wheel at the reference point, heading ψ:   ``ẋ sψ − ẏ cψ = 0``
    lateral of the front wheel at ℓ ahead, steer φ:  ``ẋ s(ψ+φ) − ẏ c(ψ+φ) − ℓ ψ̇ cφ = 0``
    rolling of the front wheel: ``ẋ c(ψ+φ) + ẏ s(ψ+φ) + ℓ ψ̇ sφ − R_f θ̇_F = 0``
    rolling of a rear wheel at lateral offset ``b`` (left +): ``ẋ cψ + ẏ sψ − b ψ̇ − R θ̇ = 0``
"""

from __future__ import annotations

import numpy as np

from wmr_mujoco.analytic.checks import as_array, positive

DISC_ROWS = ("lateral", "rolling")
BICYCLE_ROWS = ("rear lateral", "front lateral", "rear rolling", "front rolling")
TRICYCLE_ROWS = ("rear lateral", "front lateral", "left rolling", "right rolling",
                 "front rolling")


def disc(q: np.ndarray, radius: float) -> np.ndarray:
    """2×4 Pfaffian matrix of the rolling disc, ``q = (x, y, φ, θ)``."""
    q = as_array("q", q, (4,))
    r = positive("radius", radius)
    c, s = np.cos(q[2]), np.sin(q[2])
    return np.array([[s, -c, 0.0, 0.0], [c, s, 0.0, -r]])


def bicycle(q: np.ndarray, wheelbase: float, rear_radius: float, front_radius: float
            ) -> np.ndarray:
    """4×6 Pfaffian matrix of the bicycle, ``q = (x, y, ψ, φ, θ_r, θ_f)``."""
    q = as_array("q", q, (6,))
    ell = positive("wheelbase", wheelbase)
    rr, rf = positive("rear_radius", rear_radius), positive("front_radius", front_radius)
    psi, phi = q[2], q[3]
    c, s = np.cos(psi), np.sin(psi)
    cf, sf = np.cos(psi + phi), np.sin(psi + phi)
    return np.array([
        [s, -c, 0.0, 0.0, 0.0, 0.0],
        [sf, -cf, -ell * np.cos(phi), 0.0, 0.0, 0.0],
        [c, s, 0.0, 0.0, -rr, 0.0],
        [cf, sf, ell * np.sin(phi), 0.0, 0.0, -rf],
    ])


def tricycle(q: np.ndarray, wheelbase: float, track: float, rear_radius: float,
             front_radius: float) -> np.ndarray:
    """5×7 Pfaffian matrix of the tricycle, ``q = (x, y, ψ, φ, θ_L, θ_R, θ_F)``."""
    q = as_array("q", q, (7,))
    ell = positive("wheelbase", wheelbase)
    half = positive("track", track) / 2.0
    rr, rf = positive("rear_radius", rear_radius), positive("front_radius", front_radius)
    psi, phi = q[2], q[3]
    c, s = np.cos(psi), np.sin(psi)
    cf, sf = np.cos(psi + phi), np.sin(psi + phi)
    return np.array([
        [s, -c, 0.0, 0.0, 0.0, 0.0, 0.0],
        [sf, -cf, -ell * np.cos(phi), 0.0, 0.0, 0.0, 0.0],
        [c, s, -half, 0.0, -rr, 0.0, 0.0],
        [c, s, half, 0.0, 0.0, -rr, 0.0],
        [cf, sf, ell * np.sin(phi), 0.0, 0.0, 0.0, -rf],
    ])


def residual(pfaffian, q: np.ndarray, qdot: np.ndarray, **geometry: float) -> np.ndarray:
    """Evaluate ``A(q_k) q̇_k`` along a trajectory.

    Args:
        pfaffian: one of :func:`disc`, :func:`bicycle`, :func:`tricycle`.
        q: (N, n) configurations, from physics or from a model.
        qdot: (N, n) their velocities.
        **geometry: the geometry arguments of ``pfaffian``.

    Returns:
        (N, m) slip speeds, m/s, one column per constraint row.
    """
    q = as_array("q", q, (None, None))
    qdot = as_array("qdot", qdot, (q.shape[0], q.shape[1]))
    return np.stack([pfaffian(qk, **geometry) @ vk for qk, vk in zip(q, qdot, strict=True)])
