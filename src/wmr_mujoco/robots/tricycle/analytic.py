"""Kinematics of the tricycle (lecture §3): common ICR, rear-wheel speeds, differential.

Reference point: the rear-axle midpoint, speed ``v``; track w (rear wheels at ±w/2, left
is +y), wheelbase ℓ, steering angle φ. All three wheels roll without slip only about one
ICR, on the rear axle line at ``R_C = ℓ / tan φ`` from the midpoint. Then::

    ψ̇ = v tan φ / ℓ,
    v_L = v (1 − k),  v_R = v (1 + k),  k = (w / 2ℓ) tan φ,
    v_F = v / cos φ   (front wheel ground speed).

A driven left wheel at ``v_L`` sets ``v = v_L / (1 − k)`` and the free right wheel
turns at ``v_R``; an open differential imposes ``(v_L + v_R)/2 = v`` and splits the
difference as above. Seen from the midpoint the motion is the bicycle's.
"""

from __future__ import annotations

import math

import numpy as np

from wmr_mujoco.analytic import bicycle
from wmr_mujoco.analytic.checks import positive


def _k(steer: float, track: float, wheelbase: float) -> float:
    """``k = w tan φ / (2ℓ)``; the checks only on a failing value (a control step calls it)."""
    if type(track) is not float or type(wheelbase) is not float or not (
            0.0 < track < math.inf and 0.0 < wheelbase < math.inf):
        positive("track", track)
        positive("wheelbase", wheelbase)
    return float(track) / (2.0 * float(wheelbase)) * math.tan(steer)


def icr_radius(steer: float, wheelbase: float) -> float:
    """Signed ICR distance from the rear-axle midpoint, ``ℓ / tan φ`` (inf if φ = 0)."""
    return bicycle.icr_radius(steer, wheelbase)


def rear_wheel_speeds(v_mid: float, steer: float, track: float, wheelbase: float
                      ) -> tuple[float, float]:
    """Ground speeds ``(v_L, v_R) = v (1 ∓ k)`` of the left and right rear wheels."""
    k = _k(steer, track, wheelbase)
    return float(v_mid * (1.0 - k)), float(v_mid * (1.0 + k))


def front_wheel_speed(v_mid: float, steer: float) -> float:
    """Front wheel ground speed ``v / cos φ``."""
    return float(v_mid / np.cos(steer))


def midpoint_speed_from_left(v_left: float, steer: float, track: float, wheelbase: float
                             ) -> float:
    """Midpoint speed when the left wheel is driven at ``v_L``: ``v = v_L / (1 − k)``.

    Raises:
        ValueError: the ICR lies on the driven wheel (k = 1), which then cannot move the
            vehicle.
    """
    k = _k(steer, track, wheelbase)
    if abs(1.0 - k) < 1e-12:
        raise ValueError(f"steer = {steer!r} puts the ICR on the driven left wheel; "
                         f"valid |tan φ| < 2ℓ/w")
    return float(v_left / (1.0 - k))


def midpoint_speeds(v_left: np.ndarray, steer: np.ndarray, track: float, wheelbase: float
                    ) -> np.ndarray:
    """:func:`midpoint_speed_from_left` elementwise, the same floats (``math.tan`` each).

    A steering angle that puts the ICR on the driven wheel gives NaN there (the caller
    falls back to :func:`midpoint_speed_from_left`, which raises).
    """
    c = float(track) / (2.0 * float(wheelbase))
    k = np.array([c * math.tan(s) for s in np.asarray(steer, float).tolist()])
    with np.errstate(divide="ignore", invalid="ignore"):  # those entries are NaN below
        v = np.asarray(v_left, float) / (1.0 - k)
    return np.where(np.abs(1.0 - k) < 1e-12, np.nan, v)


def differential_speeds(v_carrier: float, steer: float, track: float, wheelbase: float
                        ) -> tuple[float, float]:
    """Open differential with carrier speed ``(v_L + v_R)/2 = v``: returns ``(v_L, v_R)``."""
    return rear_wheel_speeds(v_carrier, steer, track, wheelbase)


def rates(q: np.ndarray, u: np.ndarray, wheelbase: float) -> np.ndarray:
    """``q̇`` of ``q = (x, y, ψ, φ)`` (midpoint, heading, steer), ``u = (v, ω)``."""
    return bicycle.rates(q, u, wheelbase)
