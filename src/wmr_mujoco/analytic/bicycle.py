"""Kinematics of the planar bicycle (lecture §2).

Configuration ``q = (x, y, ψ, φ)``: rear contact point, heading ψ of the body and rear
wheel, steering angle φ of the front wheel relative to the body; wheelbase ℓ.

With the rear-wheel ground speed ``v_r`` and steering rate ω as inputs::

    ẋ = v_r cos ψ,  ẏ = v_r sin ψ,  ψ̇ = v_r tan φ / ℓ,  φ̇ = ω.

With the front-wheel speed ``v_f`` (the lecture's input), ``v_r = v_f cos φ``, so
``ψ̇ = v_f sin φ / ℓ``. The instantaneous centre of rotation lies on the rear axle line at
``ℓ / tan φ`` from the rear contact (to the left for φ > 0).
"""

from __future__ import annotations

import numpy as np

from wmr_mujoco.analytic.checks import as_array, positive


def rates(q: np.ndarray, u: np.ndarray, wheelbase: float) -> np.ndarray:
    """``q̇`` for ``q = (x, y, ψ, φ)`` and ``u = (v_r, ω)``."""
    q = as_array("q", q, (4,))
    v, omega = as_array("u", u, (2,))
    ell = positive("wheelbase", wheelbase)
    _, _, psi, phi = q
    return np.array([v * np.cos(psi), v * np.sin(psi), v * np.tan(phi) / ell, omega])


def input_fields(q: np.ndarray, wheelbase: float) -> np.ndarray:
    """Columns ``g₁ = (cos ψ, sin ψ, tan φ/ℓ, 0)``, ``g₂ = (0, 0, 0, 1)`` (4×2)."""
    q = as_array("q", q, (4,))
    ell = positive("wheelbase", wheelbase)
    return np.array([[np.cos(q[2]), 0.0], [np.sin(q[2]), 0.0],
                     [np.tan(q[3]) / ell, 0.0], [0.0, 1.0]])


def front_speed_to_rear(v_front: float, steer: float) -> float:
    """Rear-wheel speed ``v_r = v_f cos φ``."""
    return float(v_front * np.cos(steer))


def icr_radius(steer: float, wheelbase: float) -> float:
    """Signed distance of the ICR from the rear contact along the rear axle, ``ℓ / tan φ``.

    Returns ``inf`` for φ = 0 (straight line).
    """
    ell = positive("wheelbase", wheelbase)
    t = np.tan(steer)
    return float("inf") if t == 0.0 else float(ell / t)
