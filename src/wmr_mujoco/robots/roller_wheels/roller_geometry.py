"""Roller geometry of an omni wheel and the wheels' actuation law.

An ellipsoid roller (semi-axes b, b, a; axis at d from the axle) at angle φ past the
bottom (``docs/omni-dynamics.md``; symbols of :mod:`wmr_mujoco.robots.roller_wheels.omni_hybrid`)::

    h(φ) = √(b² cos²φ + a² sin²φ)                 support along the floor normal
    R(φ) = d cos φ + h(φ)                          axle height over the contact
    x_c(φ) = R'(φ) = −d sin φ + (a² − b²) sin φ cos φ / h    contact ahead of the axle
    ρ(φ) = b² cos φ / h(φ)                         contact distance from the roller axis

Drive laws: torque (``τ = u``) or rate servo (``τ = clip(k_v (u − θ̇), ±τ_max)``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.analytic.checks import as_array, positive
from wmr_mujoco.analytic.planar import wrap_angle


def _finite(name: str, value: float) -> float:
    if not isinstance(value, (int, float, np.floating)) or not math.isfinite(value):
        raise ValueError(f"{name} = {value!r}; must be a finite number")
    return float(value)


@dataclass(frozen=True)
class RollerGeometry:
    """Ellipsoid rollers of one wheel.

    Attributes:
        axis_distance: d, roller axis to the wheel axle, m.
        half_width: b, roller semi-axes across its axis, m.
        half_length: a, roller semi-axis along its axis, m.
        angles: ζ_k, roller positions around the axle (0 at the top, towards +drive), rad.
        offsets: y_k, axial offsets along the axle direction a_i, m.
    """

    axis_distance: float
    half_width: float
    half_length: float
    angles: np.ndarray
    offsets: np.ndarray

    def __post_init__(self) -> None:
        positive("axis_distance", self.axis_distance)
        positive("half_width", self.half_width)
        positive("half_length", self.half_length)
        ang = as_array("angles", self.angles, (None,))
        off = as_array("offsets", self.offsets, (ang.size,))
        if ang.size < 2:
            raise ValueError(f"angles has {ang.size} rollers; a wheel needs at least 2")
        for name, arr in (("angles", ang), ("offsets", off)):
            arr = arr.copy()
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)

    def _h(self, phi: float | np.ndarray) -> float | np.ndarray:
        b, a = self.half_width, self.half_length
        return np.sqrt(b * b * np.cos(phi) ** 2 + a * a * np.sin(phi) ** 2)

    def rolling_radius(self, phi: float | np.ndarray) -> float | np.ndarray:
        """``R(φ) = d cos φ + h(φ)`` (elementwise on arrays)."""
        return self.axis_distance * np.cos(phi) + self._h(phi)

    def contact_ahead(self, phi: float | np.ndarray) -> float | np.ndarray:
        """``x_c(φ) = −d sin φ + (a² − b²) sin φ cos φ / h`` (= R'(φ))."""
        b, a = self.half_width, self.half_length
        return (-self.axis_distance * np.sin(phi)
                + (a * a - b * b) * np.sin(phi) * np.cos(phi) / self._h(phi))

    def contact_radius(self, phi: float | np.ndarray) -> float | np.ndarray:
        """``ρ(φ) = b² cos φ / h(φ)``: contact point to the roller axis."""
        return self.half_width ** 2 * np.cos(phi) / self._h(phi)

    def phases(self, theta: float) -> np.ndarray:
        """``φ_k = wrap(ζ_k + θ − π)`` in (−π, π]."""
        return wrap_angle(self.angles + theta - math.pi)

    def lowest(self, theta: float) -> int:
        """Index of the roller in contact: the one with the smallest |φ_k|."""
        return int(np.argmin(np.abs(self.phases(theta))))


@dataclass(frozen=True)
class Drive:
    """Actuation law of the wheels.

    Attributes:
        mode: ``"torque"`` (τ = u) or ``"rate"`` (velocity servo τ = k_v (u − θ̇)).
        gain: k_v, N·m·s/rad (rate mode).
        torque_limit: τ_max, N·m; |τ| is clamped to it in both modes.
    """

    mode: str
    torque_limit: float
    gain: float = 0.0

    def __post_init__(self) -> None:
        if self.mode not in ("torque", "rate"):
            raise ValueError(f"Drive.mode = {self.mode!r}; valid values are 'torque', 'rate'")
        if not math.isfinite(self.torque_limit) or self.torque_limit <= 0:
            raise ValueError(f"Drive.torque_limit = {self.torque_limit!r}; valid range is "
                             f"(0, inf)")
        if self.mode == "rate" and (not math.isfinite(self.gain) or self.gain <= 0):
            raise ValueError(f"Drive.gain = {self.gain!r}; a rate servo needs a gain in "
                             f"(0, inf)")

    def torques(self, u: np.ndarray, rates: np.ndarray) -> np.ndarray:
        """``τ = clip(u, ±τ_max)`` or ``clip(k_v (u − θ̇), ±τ_max)``."""
        if self.mode == "torque":
            return np.clip(u, -self.torque_limit, self.torque_limit)
        return np.clip(self.gain * (u - rates), -self.torque_limit, self.torque_limit)
