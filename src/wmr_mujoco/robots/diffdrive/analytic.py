"""Kinematics of the differential drive: a unicycle driven by two wheels on one axle.

Reference point: the axle midpoint; heading ψ; track b (left wheel at +b/2); wheel
radii R_L, R_R. Wheel ground speeds ``v_L = R_L θ̇_L``, ``v_R = R_R θ̇_R``. Both wheels
roll without slip only if the body turns about a point on the axle line (the ICR)::

    v = (v_R + v_L) / 2,     ω = ψ̇ = (v_R − v_L) / b,
    v_L = v − ω b/2,         v_R = v + ω b/2,

and the midpoint moves as the unicycle of :mod:`wmr_mujoco.analytic.unicycle`:
``ẋ = v cos ψ, ẏ = v sin ψ, ψ̇ = ω``. The ICR lies on the axle at ``y = v/ω``.

Pfaffian constraints ``A(q) q̇ = 0`` for ``q = (x, y, ψ, θ_L, θ_R)`` (c = cos ψ, s = sin ψ),
each row a contact-point slip speed in m/s::

    lateral (both wheels, the same row):   ẋ s − ẏ c = 0
    left rolling:                          ẋ c + ẏ s − (b/2) ψ̇ − R_L θ̇_L = 0
    right rolling:                         ẋ c + ẏ s + (b/2) ψ̇ − R_R θ̇_R = 0
"""

from __future__ import annotations

import numpy as np

from wmr_mujoco.analytic import unicycle
from wmr_mujoco.analytic.checks import as_array, positive

PFAFFIAN_ROWS = ("lateral", "left rolling", "right rolling")


def twist(v_left: float, v_right: float, track: float) -> tuple[float, float]:
    """``(v, ω) = ((v_R + v_L)/2, (v_R − v_L)/b)`` from the wheel ground speeds."""
    b = positive("track", track)
    return 0.5 * (v_right + v_left), (v_right - v_left) / b


def twist_from_rates(rate_left: float, rate_right: float, track: float, left_radius: float,
                     right_radius: float) -> tuple[float, float]:
    """``(v, ω)`` from wheel rates: ``v_L = R_L θ̇_L``, ``v_R = R_R θ̇_R``, then :func:`twist`.

    Unequal radii make a robot driven at equal rates turn: ``ω = θ̇ (R_R − R_L)/b``.
    """
    rl, rr = positive("left_radius", left_radius), positive("right_radius", right_radius)
    return twist(rl * rate_left, rr * rate_right, track)


def wheel_speeds(v: float, omega: float, track: float) -> tuple[float, float]:
    """``(v_L, v_R) = (v − ω b/2, v + ω b/2)``: the inverse of :func:`twist`."""
    half = positive("track", track) / 2.0
    return v - omega * half, v + omega * half


def rates(q: np.ndarray, u: np.ndarray, track: float) -> np.ndarray:
    """``q̇`` of ``q = (x, y, ψ)`` for wheel ground speeds ``u = (v_L, v_R)``."""
    v_left, v_right = as_array("u", u, (2,))
    return unicycle.rates(q, np.array(twist(v_left, v_right, track)))


def icr_offset(v: float, omega: float) -> float:
    """Signed ICR position on the axle, ``v/ω`` to the left of the midpoint (inf: ω = 0)."""
    return float(np.inf) if omega == 0 else float(v / omega)


def pfaffian(q: np.ndarray, track: float, left_radius: float, right_radius: float
             ) -> np.ndarray:
    """3×5 Pfaffian matrix of the differential drive, ``q = (x, y, ψ, θ_L, θ_R)``."""
    q = as_array("q", q, (5,))
    half = positive("track", track) / 2.0
    rl, rr = positive("left_radius", left_radius), positive("right_radius", right_radius)
    c, s = np.cos(q[2]), np.sin(q[2])
    return np.array([
        [s, -c, 0.0, 0.0, 0.0],
        [c, s, -half, -rl, 0.0],
        [c, s, half, 0.0, -rr],
    ])
