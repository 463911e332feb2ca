"""A thin disc rolling without slip on a horizontal plane (Routh §§241-244; O'Reilly 1996).

Derivation in ``docs/rolling-disc.md``. Disc of radius ``a``, mass ``m``, axial inertia
``C`` and diametral inertia ``A``. Angles: heading ψ (yaw of the horizontal diameter
through the contact), lean θ (wheel plane from vertical; θ > 0 tips the top toward the
heading's right, −y when heading +x), spin φ about the axle. Tilted (non-spinning) frame::

    ê1 = (cos ψ, sin ψ, 0)                       horizontal, along the rolling direction
    ê2 = (−sin ψ cos θ, cos ψ cos θ, sin θ)      the axle
    ê3 = ê1 × ê2                                 contact point → centre

Disc angular velocity in that frame: ``ω = (ω1, ω2, ω3) = (θ̇, φ̇ + ψ̇ sin θ, ψ̇ cos θ)``.
Rolling (contact point at rest): ``v_G = ω × a ê3 = a (ω2, −ω1, 0)``. Newton–Euler about
the centre with the contact force eliminated::

    (A + m a²) ω̇1 = −A ω3² tan θ + (C + m a²) ω2 ω3 + m g a sin θ
    (C + m a²) ω̇2 = −m a² ω1 ω3
             A ω̇3 = A ω1 ω3 tan θ − C ω1 ω2

Kinematics: ``θ̇ = ω1``, ``ψ̇ = ω3 / cos θ``, ``φ̇ = ω2 − ω3 tan θ``, and the contact point
moves along ê1 at ``a φ̇``: ``ẋ_P = a φ̇ cos ψ``, ``ẏ_P = a φ̇ sin ψ``.
Energy ``E = ½ m a² (ω1² + ω2²) + ½ (A ω1² + C ω2² + A ω3²) + m g a cos θ`` is conserved.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.analytic.checks import as_array, positive

GRAVITY = 9.81
#: State layout of :meth:`RollingDisc.rhs`.
STATE_NAMES = ("x", "y", "heading", "lean", "spin", "w1", "w2", "w3")


def check_lean(lean: float, name: str = "lean") -> float:
    """Return ``lean`` if it is finite and in the physical range (−π/2, π/2)."""
    if not isinstance(lean, (int, float, np.floating)) or not math.isfinite(lean) \
            or abs(lean) >= math.pi / 2:
        raise ValueError(f"{name} = {lean!r} rad is not physical; valid range is "
                         f"(-{math.pi / 2:.6g}, {math.pi / 2:.6g}) rad (flat on the floor)")
    return float(lean)


def check_incline(angle: float) -> float:
    """Return ``angle`` if it is finite and in [0, π/2)."""
    if not isinstance(angle, (int, float, np.floating)) or not math.isfinite(angle) \
            or not 0.0 <= angle < math.pi / 2:
        raise ValueError(f"incline = {angle!r} rad is not physical; valid range is "
                         f"[0, {math.pi / 2:.6g}) rad (below 90°)")
    return float(angle)


def check_rate(name: str, value: float, unit: str) -> float:
    """Return ``value`` if it is finite and >= 0, else a ``ValueError`` naming it."""
    if not isinstance(value, (int, float, np.floating)) or not math.isfinite(value) \
            or value < 0:
        raise ValueError(f"{name} = {value!r} {unit} is not valid; valid range is "
                         f"[0, inf) {unit}")
    return float(value)


@dataclass(frozen=True)
class RollingDisc:
    """Thin disc rolling without slip.

    Attributes:
        radius: a, m.
        mass: m, kg.
        axial_inertia: C, kg·m².
        diametral_inertia: A, kg·m².
        gravity: g, m/s².
    """

    radius: float
    mass: float
    axial_inertia: float
    diametral_inertia: float
    gravity: float = GRAVITY

    def __post_init__(self) -> None:
        for name in ("radius", "mass", "axial_inertia", "diametral_inertia", "gravity"):
            positive(name, getattr(self, name))

    # --- equations of motion -------------------------------------------------------
    def rhs(self, t: float, state: np.ndarray) -> np.ndarray:
        """Time derivative of ``(x, y, ψ, θ, φ, ω1, ω2, ω3)`` (module docstring)."""
        x = as_array("state", state, (8,))
        _, _, psi, th, _, w1, w2, w3 = x
        a, m, big_a, c, g = (self.radius, self.mass, self.diametral_inertia,
                             self.axial_inertia, self.gravity)
        ct, tt = math.cos(th), math.tan(th)
        if ct <= 0.0:
            raise ValueError(f"lean = {th!r} rad: the disc lies flat; the rolling model "
                             f"holds for |lean| < π/2")
        spin_rate = w2 - w3 * tt
        w1d = (-big_a * w3**2 * tt + (c + m * a**2) * w2 * w3 + m * g * a * math.sin(th)) \
            / (big_a + m * a**2)
        w2d = -m * a**2 * w1 * w3 / (c + m * a**2)
        w3d = w1 * w3 * tt - c * w1 * w2 / big_a
        return np.array([a * spin_rate * math.cos(psi), a * spin_rate * math.sin(psi),
                         w3 / ct, w1, spin_rate, w1d, w2d, w3d])

    def energy(self, state: np.ndarray) -> np.ndarray:
        """Total energy ``E`` (J) of one state or of rows of states."""
        x = np.atleast_2d(np.asarray(state, float))
        th, w1, w2, w3 = x[:, 3], x[:, 5], x[:, 6], x[:, 7]
        a, m = self.radius, self.mass
        e = (0.5 * m * a**2 * (w1**2 + w2**2)
             + 0.5 * (self.diametral_inertia * (w1**2 + w3**2) + self.axial_inertia * w2**2)
             + m * self.gravity * a * np.cos(th))
        return e if np.ndim(state) == 2 else float(e[0])

    def centre(self, state: np.ndarray) -> np.ndarray:
        """Disc centre ``G = P + a ê3`` (rows of states → rows of points)."""
        x = np.atleast_2d(np.asarray(state, float))
        psi, th = x[:, 2], x[:, 3]
        a = self.radius
        e3 = np.stack([np.sin(th) * np.sin(psi), -np.sin(th) * np.cos(psi), np.cos(th)], 1)
        g = np.column_stack([x[:, 0], x[:, 1], np.zeros(len(x))]) + a * e3
        return g if np.ndim(state) == 2 else g[0]

    def centre_velocity(self, state: np.ndarray) -> np.ndarray:
        """``v_G = a ω2 ê1 − a ω1 ê2`` in world coordinates (the rolling constraint)."""
        _, _, psi, th, _, w1, w2, _ = np.asarray(state, float)
        e1 = np.array([math.cos(psi), math.sin(psi), 0.0])
        e2 = np.array([-math.sin(psi) * math.cos(th), math.cos(psi) * math.cos(th),
                       math.sin(th)])
        return self.radius * (w2 * e1 - w1 * e2)

    # --- classic results -----------------------------------------------------------
    def incline_acceleration(self, incline: float) -> float:
        """Upright disc rolling straight down a slope β: ``ẍ = g sin β / (1 + C / (m a²))``."""
        beta = check_incline(incline)
        return self.gravity * math.sin(beta) / (1.0 + self.axial_inertia
                                                / (self.mass * self.radius**2))

    @property
    def critical_spin(self) -> float:
        """Spin ``Ω_c`` above which upright rolling is stable, rad/s.

        ``Ω_c² = m g a A / (C (C + m a²))`` (thin uniform disc: ``v_c² = g a / 3``).
        """
        a, m, big_a, c = (self.radius, self.mass, self.diametral_inertia,
                          self.axial_inertia)
        return math.sqrt(m * self.gravity * a * big_a / (c * (c + m * a**2)))

    @property
    def critical_speed(self) -> float:
        """``v_c = a Ω_c``, m/s."""
        return self.radius * self.critical_spin

    def lean_rate_squared(self, spin: float) -> float:
        """``λ²`` of the upright linearisation ``θ̈ = λ² θ`` at spin ``Ω`` (rad/s).

        ``λ² = (m g a − C (C + m a²) Ω² / A) / (A + m a²)``: < 0 oscillates (stable),
        > 0 falls with time constant ``1/λ``.
        """
        om = check_rate("spin", spin, "rad/s")
        a, m, big_a, c = (self.radius, self.mass, self.diametral_inertia,
                          self.axial_inertia)
        return (m * self.gravity * a - c * (c + m * a**2) * om**2 / big_a) / (big_a + m * a**2)

    def steady_residual(self, lean: float, heading_rate: float, w2: float) -> float:
        """Residual of steady rolling at constant lean (ω1 = 0), N·m.

        ``A ψ̇² sin θ cos θ − (C + m a²) ω2 ψ̇ cos θ − m g a sin θ = 0``.
        """
        th = check_lean(lean)
        a, m, big_a, c = (self.radius, self.mass, self.diametral_inertia,
                          self.axial_inertia)
        return (big_a * heading_rate**2 * math.sin(th) * math.cos(th)
                - (c + m * a**2) * w2 * heading_rate * math.cos(th)
                - m * self.gravity * a * math.sin(th))

    def steady_motion(self, lean: float, radius: float) -> SteadyMotion:
        """Steady circular rolling at ``lean`` θ > 0 along a contact circle of ``radius`` R.

        The contact point circles at ``a φ̇ = R Ω_p`` with heading rate ``ψ̇ = −Ω_p``
        (turning toward the lean); ``ω2 = Ω_p (R/a − sin θ)``. Substituting into the
        steady relation::

            Ω_p² = m g a sin θ / (cos θ [A sin θ + (C + m a²)(R/a − sin θ)])

        Raises:
            ValueError: lean outside (0, π/2) or a radius with no steady motion.
        """
        th = check_lean(lean)
        if th <= 0:
            raise ValueError(f"lean = {lean!r} rad; steady circling needs a lean in "
                             f"(0, {math.pi / 2:.6g}) rad")
        positive("radius", radius)
        a, m, big_a, c = (self.radius, self.mass, self.diametral_inertia,
                          self.axial_inertia)
        s = math.sin(th)
        den = math.cos(th) * (big_a * s + (c + m * a**2) * (radius / a - s))
        r_min = a * s * (1.0 - big_a / (c + m * a**2))
        if den <= 0:
            raise ValueError(f"radius = {radius!r} m has no steady motion at lean "
                             f"{lean!r} rad; valid range is ({r_min:g}, inf) m")
        om_p = math.sqrt(m * self.gravity * a * s / den)
        return SteadyMotion(lean=th, radius=radius, heading_rate=-om_p,
                            spin_rate=radius * om_p / a, w2=om_p * (radius / a - s),
                            w3=-om_p * math.cos(th), disc_radius=self.radius)

    def steady_lean(self, spin_rate: float, heading_rate: float) -> float:
        """Lean θ of steady rolling for given ``φ̇`` and ``ψ̇`` (the relation solved for θ).

        Solves ``steady_residual(θ, ψ̇, φ̇ + ψ̇ sin θ) = 0`` on (0, π/2) by bisection
        (``ψ̇ < 0`` turns toward θ > 0). Raises ``ValueError`` if there is no root.
        """
        check_rate("spin_rate", spin_rate, "rad/s")
        if not math.isfinite(heading_rate) or heading_rate >= 0:
            raise ValueError(f"heading_rate = {heading_rate!r} rad/s; valid range is "
                             f"(-inf, 0) rad/s (turning toward a lean θ > 0)")

        def f(th: float) -> float:
            return self.steady_residual(th, heading_rate,
                                        spin_rate + heading_rate * math.sin(th))
        lo, hi = 1e-9, math.pi / 2 - 1e-9
        if f(lo) * f(hi) > 0:
            raise ValueError(f"no steady lean for spin_rate = {spin_rate!r} rad/s and "
                             f"heading_rate = {heading_rate!r} rad/s")
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if f(lo) * f(mid) <= 0:
                hi = mid
            else:
                lo = mid
        return 0.5 * (lo + hi)

    def initial_state(self, lean: float, speed: float, lean_rate: float = 0.0,
                      heading_rate: float = 0.0) -> np.ndarray:
        """State at the origin heading +x: lean θ, contact speed ``a φ̇ = speed``."""
        th = check_lean(lean)
        v = check_rate("speed", speed, "m/s")
        spin = v / self.radius
        return np.array([0.0, 0.0, 0.0, th, 0.0, lean_rate,
                         spin + heading_rate * math.sin(th), heading_rate * math.cos(th)])


@dataclass(frozen=True)
class SteadyMotion:
    """A steady circular rolling motion (all rates in rad/s, lengths in m)."""

    lean: float
    radius: float
    heading_rate: float
    spin_rate: float
    w2: float
    w3: float
    disc_radius: float

    @property
    def state(self) -> np.ndarray:
        """Initial state ``(0, 0, 0, θ, 0, 0, ω2, ω3)``."""
        return np.array([0.0, 0.0, 0.0, self.lean, 0.0, 0.0, self.w2, self.w3])

    @property
    def period(self) -> float:
        """Time of one full circle, ``2π / |ψ̇|``."""
        return 2 * math.pi / abs(self.heading_rate)

    @property
    def centre_radius(self) -> float:
        """Radius of the disc centre's circle, ``R − a sin θ``."""
        return self.radius - self.disc_radius * math.sin(self.lean)

    @property
    def speed(self) -> float:
        """Contact point speed ``a φ̇``."""
        return self.disc_radius * self.spin_rate
