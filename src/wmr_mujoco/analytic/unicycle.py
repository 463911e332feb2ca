"""Kinematics of a single wheel: the unicycle (lecture §1).

Configuration ``q = (x, y, φ)``: contact point and heading of the wheel plane.
Inputs: forward speed ``v = R θ̇`` and steering rate ``ω``::

    ẋ = v cos φ,   ẏ = v sin φ,   φ̇ = ω.

Rolling without slip forbids velocity across the wheel plane::

    ẋ sin φ − ẏ cos φ = 0.
"""

from __future__ import annotations

import numpy as np

from wmr_mujoco.analytic.checks import as_array


def rates(q: np.ndarray, u: np.ndarray) -> np.ndarray:
    """``q̇ = g₁(q) v + g₂ ω`` for ``q = (x, y, φ)``, ``u = (v, ω)``."""
    q = as_array("q", q, (3,))
    v, omega = as_array("u", u, (2,))
    return np.array([v * np.cos(q[2]), v * np.sin(q[2]), omega])


def input_fields(q: np.ndarray) -> np.ndarray:
    """Columns ``g₁ = (cos φ, sin φ, 0)``, ``g₂ = (0, 0, 1)``, as a 3×2 matrix."""
    q = as_array("q", q, (3,))
    return np.array([[np.cos(q[2]), 0.0], [np.sin(q[2]), 0.0], [0.0, 1.0]])


def constant_input_pose(q0: np.ndarray, v: float, omega: float, t: np.ndarray) -> np.ndarray:
    """Closed-form pose after time ``t`` of constant inputs (a circle, or a line if ω = 0).

    ``φ(t) = φ₀ + ω t``; for ω ≠ 0: ``x = x₀ + (v/ω)(sin φ − sin φ₀)``,
    ``y = y₀ − (v/ω)(cos φ − cos φ₀)``.

    Returns:
        Array (len(t), 3).
    """
    x0, y0, p0 = as_array("q0", q0, (3,))
    t = np.atleast_1d(as_array("t", t, (None,)) if np.ndim(t) else np.array([t], float))
    phi = p0 + omega * t
    if abs(omega) < 1e-12:
        return np.stack([x0 + v * t * np.cos(p0), y0 + v * t * np.sin(p0), phi], axis=1)
    rad = v / omega
    return np.stack([x0 + rad * (np.sin(phi) - np.sin(p0)),
                     y0 - rad * (np.cos(phi) - np.cos(p0)), phi], axis=1)
