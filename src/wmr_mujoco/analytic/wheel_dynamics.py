"""Dynamics of one wheel driven by an axle torque (lecture §5).

A wheel of radius R and axial inertia J carries a translating mass m (the wheel plus
whatever rides on it). Axle torque τ, traction force F_T at the ground (positive forward),
normal force N::

    translation:  m ẍ = F_T
    rotation:     J θ̈ = τ − F_T R

Rolling (``ẋ = R θ̇``, so ``ẍ = R θ̈``) closes the system::

    ẍ = τ R / (J + m R²),    F_T = m τ R / (J + m R²).

Rolling holds while ``|F_T| ≤ μ N``, i.e. ``|τ| ≤ μ N (J + m R²) / (m R)``. Beyond it the
contact slips and kinetic friction ``F_T = μ N sign(R θ̇ − ẋ)`` drives both equations.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr_mujoco.analytic.checks import non_negative, positive

GRAVITY = 9.81


@dataclass(frozen=True)
class WheelDynamics:
    """One wheel and the mass it carries.

    Attributes:
        mass: translating mass m, kg.
        inertia: wheel inertia J about the axle, kg·m².
        radius: R, m.
        friction: Coulomb coefficient μ.
        normal_force: N, newtons; None for ``m g``.
    """

    mass: float
    inertia: float
    radius: float
    friction: float = 1.0
    normal_force: float | None = None

    def __post_init__(self) -> None:
        positive("mass", self.mass)
        positive("inertia", self.inertia)
        positive("radius", self.radius)
        non_negative("friction", self.friction)
        if self.normal_force is not None:
            non_negative("normal_force", self.normal_force)

    @property
    def normal(self) -> float:
        """Normal force N."""
        return self.mass * GRAVITY if self.normal_force is None else self.normal_force

    @property
    def effective_mass(self) -> float:
        """``m + J / R²``: the mass the torque accelerates while rolling."""
        return self.mass + self.inertia / self.radius**2

    def rolling_acceleration(self, torque: float) -> float:
        """``ẍ = τ R / (J + m R²)``."""
        return float(torque * self.radius / (self.inertia + self.mass * self.radius**2))

    def traction_force(self, torque: float) -> float:
        """Traction needed to roll: ``F_T = m τ R / (J + m R²)``."""
        return self.mass * self.rolling_acceleration(torque)

    @property
    def max_rolling_torque(self) -> float:
        """Largest |τ| that still rolls: ``μ N (J + m R²) / (m R)``."""
        return float(self.friction * self.normal * (self.inertia + self.mass * self.radius**2)
                     / (self.mass * self.radius))

    def slips(self, torque: float) -> bool:
        """True when the traction needed to roll exceeds ``μ N``."""
        return abs(self.traction_force(torque)) > self.friction * self.normal

    def accelerations(self, torque: float, speed: float, spin: float,
                      tol: float = 1e-9) -> tuple[float, float]:
        """``(ẍ, θ̈)`` for the state ``(ẋ, θ̇)``: rolling or slipping.

        Rolling when the contact is not sliding (``|R θ̇ − ẋ| ≤ tol``) and the torque is
        below the friction limit; otherwise kinetic friction ``μ N`` opposes the slip
        (or, at the instant slip starts, acts in the torque's direction).
        """
        slip = self.radius * spin - speed
        if abs(slip) <= tol and not self.slips(torque):
            a = self.rolling_acceleration(torque)
            return a, a / self.radius
        direction = np.sign(slip) if abs(slip) > tol else np.sign(torque)
        force = self.friction * self.normal * direction
        return float(force / self.mass), float((torque - force * self.radius) / self.inertia)


@dataclass(frozen=True)
class SlipPulse:
    """Closed-form response of a wheel at rest to a torque pulse above the traction limit.

    Torque ``τ > τ_max`` (:attr:`WheelDynamics.max_rolling_torque`) for ``0 ≤ t < t_1``,
    then zero. Kinetic friction ``μN`` (slip ``s = R θ̇ − ẋ > 0``) acts throughout the
    sliding phase::

        pulse:   ẍ = μN/m,   θ̈_1 = (τ − μN R)/J,   ṡ_1 = R θ̈_1 − μN/m > 0
        coast:   ẍ = μN/m,   θ̈_2 = −μN R/J,        ṡ_2 = −μN (R²/J + 1/m)

    The wheel grips again when ``R θ̇ = ẋ``: ``t_g = t_1 + s(t_1)/|ṡ_2|`` with
    ``s(t_1) = ṡ_1 t_1``; afterwards it rolls on at the constant speed ``ẋ(t_g)``.

    Attributes:
        wheel: the wheel model.
        torque: pulse torque τ, N·m.
        on_time: pulse length t_1, s.
    """

    wheel: WheelDynamics
    torque: float
    on_time: float

    def __post_init__(self) -> None:
        positive("on_time", self.on_time)
        limit = self.wheel.max_rolling_torque
        if not np.isfinite(self.torque) or self.torque <= limit:
            raise ValueError(f"torque = {self.torque!r} N·m does not slip; valid range is "
                             f"({limit:g}, inf) N·m (above the traction limit)")

    @property
    def friction_force(self) -> float:
        """Kinetic friction ``μ N``, N."""
        return self.wheel.friction * self.wheel.normal

    @property
    def linear_acceleration(self) -> float:
        """``ẍ = μN/m`` while sliding, m/s²."""
        return self.friction_force / self.wheel.mass

    @property
    def spin_acceleration(self) -> float:
        """``θ̈_1 = (τ − μN R)/J`` during the pulse, rad/s²."""
        w = self.wheel
        return (self.torque - self.friction_force * w.radius) / w.inertia

    @property
    def coast_spin_acceleration(self) -> float:
        """``θ̈_2 = −μN R/J`` after the pulse, still sliding, rad/s²."""
        return -self.friction_force * self.wheel.radius / self.wheel.inertia

    @property
    def regrip_time(self) -> float:
        """``t_g = t_1 + ṡ_1 t_1 / |ṡ_2|``, s."""
        w = self.wheel
        s1 = w.radius * self.spin_acceleration - self.linear_acceleration
        s2 = w.radius * self.coast_spin_acceleration - self.linear_acceleration
        return self.on_time * (1.0 + s1 / -s2)

    def state(self, t: np.ndarray) -> np.ndarray:
        """Rows ``(x, ẋ, θ̇)`` at times ``t`` (s), piecewise closed form."""
        t = np.asarray(t, float)
        t1, tg = self.on_time, self.regrip_time
        a, r = self.linear_acceleration, self.wheel.radius
        ts = np.minimum(t, tg)
        speed = a * ts
        x = 0.5 * a * ts**2 + speed * np.maximum(t - tg, 0.0)
        spin = (self.spin_acceleration * np.minimum(ts, t1)
                + self.coast_spin_acceleration * np.maximum(ts - t1, 0.0))
        spin = np.where(t >= tg, speed / r, spin)
        return np.column_stack([x, speed, spin])
