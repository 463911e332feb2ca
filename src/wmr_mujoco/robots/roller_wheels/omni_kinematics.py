"""Kinematics of omni (Swedish) and mecanum wheeled platforms (lecture §4).

Body velocity ``ν = (u, v, r)``: forward and left speed of the platform centre in the
platform's own frame, and yaw rate ``r = ψ̇``. World rates: ``(Ẋ, Ẏ) = Rot(ψ) (u, v)``.

General wheel (Lynch & Park, *Modern Robotics* §13.2): wheel i at ``(x_i, y_i)`` in the
body frame, driving direction β_i (direction the wheel rolls when θ̇_i > 0), roller angle
γ_i (0 for omni wheels, ±π/4 for mecanum), radius r_i::

    θ̇_i = 1/(r_i cos γ_i) [cos(β_i+γ_i),  sin(β_i+γ_i),  x_i sin(β_i+γ_i) − y_i cos(β_i+γ_i)] ν

Stacked, ``θ̇ = H ν``. The lecture's three omni wheels at α_i = 0°, 120°, 240° on a circle
of radius L, each driving tangentially (β_i = α_i + 90°), give ``H = J / r`` with::

    J = [[0, 1, L], [−√3/2, −1/2, L], [√3/2, −1/2, L]],   row i = (−sin α_i, cos α_i, L).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.analytic.checks import as_array, positive


@dataclass(frozen=True)
class WheelLayout:
    """Geometry of n wheels on a platform.

    Attributes:
        positions: (n, 2) wheel contact positions in the body frame, m.
        drive_angles: (n,) driving directions β_i, rad.
        roller_angles: (n,) roller angles γ_i, rad (|γ| < π/2).
        radii: (n,) wheel radii, m.
    """

    positions: np.ndarray
    drive_angles: np.ndarray
    roller_angles: np.ndarray
    radii: np.ndarray

    def __post_init__(self) -> None:
        pos = as_array("positions", self.positions, (None, 2))
        n = pos.shape[0]
        if n < 3:
            raise ValueError(f"positions has {n} wheels; a platform needs at least 3")
        beta = as_array("drive_angles", self.drive_angles, (n,))
        gamma = as_array("roller_angles", self.roller_angles, (n,))
        radii = as_array("radii", self.radii, (n,))
        if np.any(np.abs(gamma) >= np.pi / 2 - 1e-6):
            raise ValueError(f"roller_angles = {gamma}; each must lie in (−π/2, π/2)")
        if np.any(radii <= 0):
            raise ValueError(f"radii = {radii}; each must be > 0")
        for name, arr in (("positions", pos), ("drive_angles", beta),
                          ("roller_angles", gamma), ("radii", radii)):
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)

    @property
    def n(self) -> int:
        """Number of wheels."""
        return self.positions.shape[0]

    @functools.cached_property
    def slide_terms(self) -> tuple[tuple[float, float, float, float, float], ...]:
        """Per wheel ``(x_i, y_i, cos(β_i+γ_i), sin(β_i+γ_i), tan γ_i)``, as Python floats.

        What :func:`roller_slide_speeds` reads of the layout (computed once).
        """
        ang = self.drive_angles + self.roller_angles
        x, y = self.positions.T
        return tuple(zip(x.tolist(), y.tolist(), np.cos(ang).tolist(), np.sin(ang).tolist(),
                         np.tan(self.roller_angles).tolist(), strict=True))


def symmetric_layout(radius: float, distance: float, n: int = 3, first_angle: float = 0.0,
                     roller_angle: float = 0.0) -> WheelLayout:
    """N wheels at angles ``α_i = first_angle + 2πi/n`` on a circle of radius L, tangential.

    With n = 3, first_angle = 0 and roller_angle = 0 this is the lecture's robot.
    """
    positive("radius", radius)
    L = positive("distance", distance)
    if not isinstance(n, int) or n < 3:
        raise ValueError(f"n = {n!r}; a platform needs an integer number of wheels >= 3")
    alpha = first_angle + 2.0 * np.pi * np.arange(n) / n
    return WheelLayout(L * np.stack([np.cos(alpha), np.sin(alpha)], axis=1),
                       alpha + np.pi / 2.0, np.full(n, float(roller_angle)),
                       np.full(n, float(radius)))


def mecanum_layout(radius: float, half_length: float, half_width: float) -> WheelLayout:
    """Four mecanum wheels (front-left, front-right, rear-left, rear-right), rollers ±45°.

    All wheels drive along +x; the rollers form the usual X pattern seen from above.
    """
    a, b = positive("half_length", half_length), positive("half_width", half_width)
    pos = np.array([[a, b], [a, -b], [-a, b], [-a, -b]])
    gamma = np.array([-1.0, 1.0, 1.0, -1.0]) * np.pi / 4.0
    return WheelLayout(pos, np.zeros(4), gamma, np.full(4, positive("radius", radius)))


def wheel_jacobian(layout: WheelLayout) -> np.ndarray:
    """``H`` (n×3) with ``θ̇ = H ν`` (Lynch & Park's formula, see the module docstring)."""
    bg = layout.drive_angles + layout.roller_angles
    x, y = layout.positions.T
    rows = np.stack([np.cos(bg), np.sin(bg), x * np.sin(bg) - y * np.cos(bg)], axis=1)
    return rows / (layout.radii * np.cos(layout.roller_angles))[:, None]


def lecture_matrix(distance: float) -> np.ndarray:
    """The lecture's matrix J, written out: ``θ̇ = (1/r) J ν``."""
    L = positive("distance", distance)
    s = np.sqrt(3.0) / 2.0
    return np.array([[0.0, 1.0, L], [-s, -0.5, L], [s, -0.5, L]])


def wheel_rates(layout: WheelLayout, nu: np.ndarray) -> np.ndarray:
    """Wheel rates ``θ̇ = H ν`` (rad/s) for a body twist ``ν = (u, v, r)``."""
    return wheel_jacobian(layout) @ as_array("nu", nu, (3,))


def body_twist(layout: WheelLayout, rates: np.ndarray) -> np.ndarray:
    """Body twist from wheel rates: ``ν = H⁻¹ θ̇`` (least squares if n > 3).

    Raises:
        ValueError: ``H`` has rank < 3 (the layout cannot move in every direction).
    """
    H = wheel_jacobian(layout)
    rates = as_array("rates", rates, (layout.n,))
    if np.linalg.matrix_rank(H) < 3:
        raise ValueError("wheel layout has a Jacobian of rank < 3: not omnidirectional")
    return np.linalg.lstsq(H, rates, rcond=None)[0]


def roller_slide_speeds(layout: WheelLayout, nu: np.ndarray) -> np.ndarray:
    """Speed the passive rollers take up at each contact, under the ideal wheel rates.

    The contact roller turns about ``e_i = (cos(β_i+γ_i), sin(β_i+γ_i))``; its surface
    carries the contact's velocity relative to the rim, ``v_c − R θ̇ d_i``, across that
    axis, along ``n_i = ẑ × e_i``. With ``R θ̇_i = v_c·e_i / cos γ_i`` (Lynch & Park) and
    ``d_i·n_i = −sin γ_i`` this is ``−(v_c·n_i + tan γ_i v_c·e_i)``, with ``v_c = v + r ẑ × p_i``.
    For omni wheels (γ = 0) it is the speed along the axle ``a_i · v_c``,
    ``a_i = (sin β_i, −cos β_i)``. A roller of rolling radius ρ spins at this speed / ρ.
    """
    u, v, r = as_array("nu", nu, (3,)).tolist()
    # Per wheel in Python floats: the elementwise arithmetic of the (n,) arrays, the same
    # floats; the layout's cosines, sines and tangents once per layout.
    out = []
    for x, y, c, s, t in layout.slide_terms:
        vx, vy = u - r * y, v + r * x
        out.append(-((-s * vx + c * vy) + t * (c * vx + s * vy)))
    return np.array(out)


def rotation(psi: float) -> np.ndarray:
    """Planar rotation ``Rot(ψ)`` (2×2)."""
    c, s = np.cos(psi), np.sin(psi)
    return np.array([[c, -s], [s, c]])


def body_to_world(psi: float, nu: np.ndarray) -> np.ndarray:
    """``(Ẋ, Ẏ, ψ̇) = (Rot(ψ)(u, v), r)``."""
    u, v, r = as_array("nu", nu, (3,)).tolist()
    c, s = math.cos(psi), math.sin(psi)  # scalar arithmetic: the integrators' hot path
    return np.array([c * u - s * v, s * u + c * v, r])


def world_to_body(psi: float, world_rates: np.ndarray) -> np.ndarray:
    """``ν = (Rot(ψ)ᵀ(Ẋ, Ẏ), ψ̇)``."""
    x, y, r = as_array("world_rates", world_rates, (3,)).tolist()
    c, s = math.cos(psi), math.sin(psi)
    return np.array([c * x + s * y, -s * x + c * y, r])
