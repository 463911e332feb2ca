"""The ideal mecanum roller profile and its osculating ellipsoid (derivation: docs/mecanum.md).

Wheel frame: x the drive direction, y the axle, z up; the wheel's envelope is the cylinder
``x² + z² = R²`` about y. The roller at the bottom has its axis through ``(0, 0, −d)``,
``d = R − b``, along ``u = (c, s, 0)`` with ``c = cos γ``, ``s = sin γ`` (γ the roller
angle against the drive direction). A surface of revolution about that axis touches the
cylinder along a curve iff it is the envelope of the spheres centred at the axis points
``P(t) = (c t, s t, −d)`` with radius equal to their distance to the cylinder::

    q(t) = √(d² + c² t²),   λ(t) = R − q(t),   sin φ(t) = c t / q(t)

The sphere at ``P(t)`` touches the cylinder at wheel angle φ(t); that point lies on the
envelope (its axial offset from ``P`` is ``λ c sin φ = −λ λ'``), so the roller's meridian
is, in roller coordinates (axial σ, radius ρ)::

    σ(t) = t + λ(t) c² t / q(t),     ρ(t) = λ(t) √(1 − c⁴ t² / q(t)²)

At the middle ``ρ(0) = b`` and the meridian's curvature is ``κ = c² / (d + b c²)``
(γ = 0: ``1/R``, the omni barrel; γ = 45°: ``1/(2R − b)``). An ellipsoid with semi-axes
``(b, b, A)``, ``A² = b (d + b c²) / c²``, osculates the profile there in both principal
directions. When the wheel has turned by φ the roller touching the floor is tilted, and
the direction along which its contact cannot slide is ``(c cos φ, s)``, not ``(c, s)``:
the effective roller angle is ``tan γ_eff = tan γ / cos φ`` (docs/mecanum.md, §3).
"""

from __future__ import annotations

import math

import numpy as np

from wmr_mujoco.analytic.checks import positive


def _check(radius: float, half_width: float, roller_angle: float) -> tuple[float, float, float]:
    R = positive("radius", radius)
    b = positive("half_width", half_width)
    if b >= R:
        raise ValueError(f"half_width = {b!r} must be below radius = {R!r}")
    if not 0.0 <= roller_angle < math.pi / 2.0:
        raise ValueError(f"roller_angle = {roller_angle!r}; valid range is [0, π/2)")
    return R, b, float(roller_angle)


def axis_parameter(radius: float, half_width: float, roller_angle: float,
                   wheel_angle: float | np.ndarray) -> np.ndarray:
    """Axis parameter t of the sphere touching the envelope at wheel angle φ: ``d tan φ / c``."""
    R, b, g = _check(radius, half_width, roller_angle)
    return (R - b) * np.tan(wheel_angle) / math.cos(g)


def ideal_profile(radius: float, half_width: float, roller_angle: float,
                  t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Meridian ``(σ(t), ρ(t))`` of the ideal roller at axis parameters ``t`` (module doc)."""
    R, b, g = _check(radius, half_width, roller_angle)
    c = math.cos(g)
    d = R - b
    t = np.asarray(t, float)
    q = np.sqrt(d * d + c * c * t * t)
    lam = R - q
    sigma = t + lam * c * c * t / q
    rho = lam * np.sqrt(1.0 - c**4 * t * t / (q * q))
    return sigma, rho


def middle_curvature(radius: float, half_width: float, roller_angle: float) -> float:
    """Meridian curvature of the ideal roller at its middle, ``κ = c² / (d + b c²)``."""
    R, b, g = _check(radius, half_width, roller_angle)
    c2 = math.cos(g) ** 2
    return c2 / (R - b + b * c2)


def ellipsoid_semi_axis(radius: float, half_width: float, roller_angle: float) -> float:
    """Axial semi-axis A of the osculating ellipsoid ``(b, b, A)``: ``A² = b / κ``.

    An ellipsoid's meridian curvature at the end of its b semi-axis is ``b / A²``.
    """
    return math.sqrt(half_width / middle_curvature(radius, half_width, roller_angle))


def effective_roller_angle(roller_angle: float, wheel_angle: float | np.ndarray) -> np.ndarray:
    """``γ_eff = atan(tan γ / cos φ)``: the tilted contact roller's constrained direction."""
    return np.arctan(math.tan(roller_angle) / np.cos(wheel_angle))


def mean_lateral_factor(half_span: float) -> float:
    """``⟨cos φ⟩`` over ``φ ∈ [−φ_m, φ_m]``: ``sin φ_m / φ_m``.

    With wheel rates from the ideal formula, a wheel rolling sideways on rollers carries the
    chassis at ``cos φ`` of the ideal lateral speed (``R θ̇ = v_x + v_y tan γ / cos φ``);
    averaged over a roller passage the deficit is ``1 − sin φ_m / φ_m ≈ φ_m²/6``.
    """
    phi = positive("half_span", half_span)
    return math.sin(phi) / phi
