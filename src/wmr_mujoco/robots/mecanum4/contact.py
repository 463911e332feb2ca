"""Where a mecanum roller collider touches the floor, and the rolling constraint it sets.

The pitch-averaged model (:mod:`wmr_mujoco.robots.roller_wheels.pitch_averaged`) takes the ideal
profile's contact: straight below the axle at the rolling radius R, walking along the axle
by ``d tan φ tan γ``. A collider that only osculates that profile (``mecanum4``'s
ellipsoid) touches elsewhere; this module computes its contact exactly and the rolling
constraint that follows from it (docs/mecanum.md §3, "The collider's own contact").

Wheel frame: x the drive direction, y the axle, z up, origin on the axle. The roller whose
middle is at the bottom when the wheel has turned by φ has its centre and axis at::

    P(φ) = (−d sin φ, 0, −d cos φ),     u(φ) = (c cos φ, ±s, −c sin φ),

``d = R − b``, ``c = cos γ``, ``s = sin γ`` (the sign is the wheel's roller-angle sign).

**Contact.** An ellipsoid with semi-axes ``(b, b, A)`` about ``u`` is ``P + E w``,
``|w| ≤ 1``, ``E Eᵀ = b² I + (A² − b²) u uᵀ``; its lowest point (support point along
``−ẑ``) is::

    Q = P − E Eᵀ ẑ / √(ẑᵀ E Eᵀ ẑ) = P − (b² ẑ + (A² − b²) u_z u) / √(b² + (A² − b²) u_z²).

(A = b: a sphere, Q = P − b ẑ.) The ideal profile touches at ``Q = (0, ±s t, −R)``,
``t = d tan φ / c``. The rolling height is ``h = −Q_z``.

**Constraint.** Any surface of revolution about ``u`` has its normal at Q in the plane of
``u`` and ``Q − P``; the normal there is ``ẑ``, so the roller's spin moves Q along
``u × (Q − P)``, which is horizontal and perpendicular to the horizontal part of ``u``.
The contact velocity along ``e = (u_x, u_y)/|(u_x, u_y)|`` must be the rim's there,
``−h θ̇ x̂``. With the chassis twist ``ν = (u, v, r)`` and the contact at
``(X, Y) = (x_i + Q_x, y_i + Q_y)`` in the body frame (wheel i at ``(x_i, y_i)``, driving
along the body's +x)::

    θ̇_i = [1, u_y/u_x, X u_y/u_x − Y] ν / h.

The ideal profile gives ``h = R`` and ``u_y/u_x = tan γ / cos φ`` (the pitch average's
law); the collider adds its own ``h(φ)``, ``Q_x(φ)`` and ``Q_y(φ)``.

**Mean twist.** Four wheels over-constrain the chassis's three velocities, and with the
contact at ``Q(φ)`` their rows do not agree at every phase (the contact's walk along the
axle changes each wheel's lever about the centre, oddly in φ, differently on the two
diagonals). As the pitch average does, take each wheel turning uniformly at its
commanded rate from its rest phase 0 (the servos hold the rates); the contacts then take
the misfit, each with a force along its ``e_i`` that grows with its slip
``s_i = g_iᵀ ν − h_i e_x,i θ̇_i``, ``g_i = (e_i, p_i × e_i)``, at equal rates for the four
identical, equally loaded contacts. Force balance on the chassis, ``Σ F_i g_i = 0`` with
``F_i ∝ −s_i``, gives the least-squares twist in the slip::

    ν(t) = G⁺ D θ̇,    G rows g_iᵀ,  D = diag(h_i e_x,i),

and the run's mean twist is its mean over the common period of the wheels' roller
pitches. (With the servos taking the misfit instead, the least squares would be in the
wheel rates, ``H⁺ θ̇``, and the wheels would not turn uniformly: docs/mecanum.md §3.)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.analytic.checks import as_array, positive


@dataclass(frozen=True)
class RollerGeometry:
    """A wheel's rollers: envelope radius, roller thickness and angle, collider, count.

    Attributes:
        radius: R, the envelope radius, m.
        half_width: b, the roller's radius at its middle, m (0 < b < R).
        roller_angle: γ, the contact roller's angle to the drive direction at its
            middle, rad, in (0, π/2).
        rollers: n, rollers per wheel (≥ 2); the contact hands over at ``±π/n``.
        semi_axis: A, the ellipsoid collider's axial semi-axis, m (A ≥ b; A = b: a
            sphere); None: the ideal profile.
    """

    radius: float
    half_width: float
    roller_angle: float
    rollers: int
    semi_axis: float | None = None

    def __post_init__(self) -> None:
        positive("radius", self.radius)
        positive("half_width", self.half_width)
        if self.half_width >= self.radius:
            raise ValueError(f"half_width = {self.half_width!r} m must be below "
                             f"radius = {self.radius!r} m")
        if not (math.isfinite(self.roller_angle) and 0.0 < self.roller_angle < math.pi / 2):
            raise ValueError(f"roller_angle = {self.roller_angle!r} rad; valid range is "
                             "(0, π/2)")
        if (isinstance(self.rollers, bool) or not isinstance(self.rollers, (int, np.integer))
                or self.rollers < 2):
            raise ValueError(f"rollers = {self.rollers!r}; valid values are integers >= 2")
        if self.semi_axis is not None and not (math.isfinite(self.semi_axis)
                                               and self.semi_axis >= self.half_width):
            raise ValueError(f"semi_axis = {self.semi_axis!r} m; valid range is "
                             f"[half_width = {self.half_width!r}, inf) or None")

    @property
    def pitch(self) -> float:
        """Wheel angle between neighbouring rollers, ``2π/n``."""
        return 2.0 * math.pi / self.rollers


def roller_phase(geometry: RollerGeometry, wheel_angle: np.ndarray) -> np.ndarray:
    """φ of the contact roller at the wheel angle θ: θ wrapped into ``[−π/n, π/n)``."""
    p = geometry.pitch
    return (np.asarray(wheel_angle, float) + p / 2.0) % p - p / 2.0


def contact(geometry: RollerGeometry, phase: float, sign: float
            ) -> tuple[np.ndarray, np.ndarray]:
    """``(Q, u)``: the lowest point of the roller at phase φ and its axis (wheel frame).

    Args:
        geometry: the rollers.
        phase: φ, wheel angle from the contact roller's middle, rad (|φ| ≤ π/n).
        sign: the wheel's roller-angle sign, ±1.
    """
    g = geometry
    c, s = math.cos(g.roller_angle), math.copysign(math.sin(g.roller_angle), sign)
    d = g.radius - g.half_width
    u = np.array([c * math.cos(phase), s, -c * math.sin(phase)])
    if g.semi_axis is None:
        return np.array([0.0, s * d * math.tan(phase) / c, -g.radius]), u
    b2, k = g.half_width ** 2, g.semi_axis ** 2 - g.half_width ** 2
    centre = np.array([-d * math.sin(phase), 0.0, -d * math.cos(phase)])
    lowest = centre - (b2 * np.array([0.0, 0.0, 1.0]) + k * u[2] * u) / math.sqrt(
        b2 + k * u[2] ** 2)
    return lowest, u


def slip_rows(geometry: RollerGeometry, positions: np.ndarray, signs: np.ndarray,
              wheel_angles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(G, D)``: contact slip ``s = G ν − D θ̇`` along each contact's ``e`` at the angles θ.

    Row i of G is ``(e_x, e_y, X e_y − Y e_x)`` (the contact's velocity along ``e``),
    ``D_i = h e_x`` (the rim's); the rolling rows are ``H = G / D`` (module docstring).
    """
    pos = as_array("positions", positions, (None, 2))
    n = pos.shape[0]
    sg = as_array("signs", signs, (n,))
    th = as_array("wheel_angles", wheel_angles, (n,))
    g = np.empty((n, 3))
    rim = np.empty(n)
    for i, phase in enumerate(roller_phase(geometry, th)):
        q, u = contact(geometry, float(phase), float(sg[i]))
        e = u[:2] / math.hypot(u[0], u[1])
        x, y = pos[i, 0] + q[0], pos[i, 1] + q[1]
        g[i] = (e[0], e[1], x * e[1] - y * e[0])
        rim[i] = -q[2] * e[0]
    return g, rim


def constraint_rows(geometry: RollerGeometry, positions: np.ndarray, signs: np.ndarray,
                    wheel_angles: np.ndarray) -> np.ndarray:
    """(n, 3) rows ``θ̇_i = [1, u_y/u_x, X u_y/u_x − Y] ν / h`` at the wheel angles θ."""
    g, rim = slip_rows(geometry, positions, signs, wheel_angles)
    return g / rim[:, None]


#: Samples of :func:`mean_twist` evaluated together (bounds its memory: a wheel turning
#: far slower than the others asks for many samples, taken this many at a time).
CHUNK = 4096


def contact_arrays(geometry: RollerGeometry, phase: np.ndarray, sign: np.ndarray
                   ) -> tuple[np.ndarray, np.ndarray]:
    """:func:`contact` at many phases at once: ``(Q, u)``, each ``phase.shape + (3,)``.

    ``sign`` broadcasts against ``phase`` (one wheel's sign per column). The same
    formulas as :func:`contact`, elementwise.
    """
    g = geometry
    c = math.cos(g.roller_angle)
    s = np.copysign(math.sin(g.roller_angle), sign) * np.ones_like(phase)
    d = g.radius - g.half_width
    uz = -c * np.sin(phase)
    u = np.stack([c * np.cos(phase), s, uz], axis=-1)
    if g.semi_axis is None:
        return np.stack([np.zeros_like(phase), s * d * np.tan(phase) / c,
                         np.full_like(phase, -g.radius)], axis=-1), u
    b2, k = g.half_width ** 2, g.semi_axis ** 2 - g.half_width ** 2
    norm = np.sqrt(b2 + k * uz ** 2)
    lowest = np.stack([-d * np.sin(phase) - k * uz * u[..., 0] / norm,
                       -k * uz * u[..., 1] / norm,
                       -d * np.cos(phase) - (b2 + k * uz * uz) / norm], axis=-1)
    return lowest, u


def slip_rows_at(geometry: RollerGeometry, positions: np.ndarray, signs: np.ndarray,
                 wheel_angles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """:func:`slip_rows` at many sets of wheel angles at once.

    ``wheel_angles`` (k, n) gives ``G`` (k, n, 3) and ``D`` (k, n).
    """
    q, u = contact_arrays(geometry, roller_phase(geometry, wheel_angles), signs[None, :])
    e = u[..., :2] / np.hypot(u[..., 0], u[..., 1])[..., None]
    x = positions[None, :, 0] + q[..., 0]
    y = positions[None, :, 1] + q[..., 1]
    g = np.stack([e[..., 0], e[..., 1], x * e[..., 1] - y * e[..., 0]], axis=-1)
    return g, -q[..., 2] * e[..., 0]


def mean_twist(geometry: RollerGeometry, positions: np.ndarray, signs: np.ndarray,
               rates: np.ndarray, samples: int = 128) -> np.ndarray:
    """Mean of ``G(φ(t))⁺ D(φ(t)) θ̇`` with ``θ_i = θ̇_i t`` from the rest phase 0.

    The twist that minimises the summed squared contact slip (module docstring), averaged
    over the period of the slowest turning wheel's roller pitch,
    ``2π / (n min |θ̇_i|)``, at ``samples`` times per pitch of the fastest one: exact in
    the limit when every turning wheel's rate is a whole multiple of the slowest one's
    (true of ``mecanum4``'s runs: equal rates, or 1 : 3 for its translate+rotate).

    The samples are evaluated together, :data:`CHUNK` at a time (:func:`slip_rows_at`;
    each sample's least squares by the pseudo-inverse of its 4×3 ``G``): the sampled
    twists of :func:`slip_rows` and ``lstsq`` one by one, to round-off.

    Raises:
        ValueError: no wheel turns, or ``samples`` below 8.
    """
    w = as_array("rates", rates, (None,))
    if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples < 8:
        raise ValueError(f"samples = {samples!r}; valid values are integers >= 8")
    turning = np.abs(w[np.abs(w) > 1e-12])
    if turning.size == 0:
        raise ValueError(f"rates = {w}: no wheel turns")
    pos = as_array("positions", positions, (w.size, 2))
    sg = as_array("signs", signs, (w.size,))
    period = geometry.pitch / float(np.min(turning))
    count = int(samples * math.ceil(float(np.max(turning) / np.min(turning))))
    total = np.zeros(3)
    for start in range(0, count, CHUNK):
        t = (np.arange(start, min(count, start + CHUNK)) + 0.5) * period / count
        g, rim = slip_rows_at(geometry, pos, sg, w[None, :] * t[:, None])
        total += np.einsum("kij,kj->i", np.linalg.pinv(g), rim * w[None, :])
    return total / count
