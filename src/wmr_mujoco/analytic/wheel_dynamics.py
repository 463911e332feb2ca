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
