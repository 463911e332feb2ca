"""Normal loads of a three-omni-wheel platform: its balance at the contacts, and heave.

:func:`balance_loads`: the loads that hold the platform's weight and the tractions'
moments (load transfer), supported at the contact points themselves: ``(L − y_σ) ê_i +
x_c t_i`` moves with the roller phase by the row offset ``e`` and the contact's lead
``x_c`` (4 % and up to 6.5 % of L), which shifts the loads by as much.

Heave (:func:`contact_inertia`, :func:`heave_loads`), the platform riding over its
rollers' arcs:

On rigid contacts each wheel centre stands ``z_i = R(φ_i)`` above the floor (the axle
height over the contact, :class:`~wmr_mujoco.robots.roller_wheels.roller_geometry.RollerGeometry`),
so as the wheels turn the platform heaves, rolls and pitches with them. With the wheel
centres at body positions ``(x_i, y_i)`` and small tilts, the heights are those of a
plane::

    z_i = z_c + α y_i − β x_i,      A = [1, y_i, −x_i] (rows),   (z_c, α, β) = A⁻¹ z

(α the roll about x, β the pitch about y). Newton–Euler for the vertical force and the
horizontal moments about the centre (the tractions' own moments are the load transfer
of :meth:`~wmr_mujoco.robots.roller_wheels.omni_hybrid.OmniHybrid.normal_loads`, added apart)::

    Σ ΔN_i = M z̈_c,   Σ y_i ΔN_i = I_xx α̈,   −Σ x_i ΔN_i = I_yy β̈

i.e. ``Aᵀ ΔN = D A⁻¹ z̈`` with ``D = diag(M, I_xx, I_yy)``, so

    ΔN = K z̈,   K = A⁻ᵀ D A⁻¹   (the platform's inertia seen at the three contacts),
    z̈_i = R'(φ_i) θ̈_i + R''(φ_i) θ̇_i²     (φ̇ = θ̇, x_c = R').

A wheel driven hard (θ̈ large) on the part of a roller where its axle sinks (``R' θ̈ <
0``) loses load, and its traction limit ``μ N`` with it: the slip onset depends on the
phase of the wheels within a roller pitch. Left out: the kink of R at a hand-over (an
impulse, not a load) and the tilts' gyroscopic terms with the yaw rate.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from wmr_mujoco.robots.roller_wheels.omni_batch import _Geometry
    from wmr_mujoco.robots.roller_wheels.omni_hybrid import OmniHybrid


def contact_inertia(positions: np.ndarray, mass: float, roll_inertia: float,
                    pitch_inertia: float) -> np.ndarray:
    """``K = A⁻ᵀ diag(M, I_xx, I_yy) A⁻¹`` (module docstring), N·s²/m.

    Args:
        positions: (3, 2) body-frame ``(x_i, y_i)`` of the wheel centres, m (not collinear).
        mass: M, kg.
        roll_inertia: I_xx about the centre, kg·m².
        pitch_inertia: I_yy about the centre, kg·m².

    Raises:
        ValueError: not three non-collinear positions, or a non-positive inertia.
    """
    p = np.asarray(positions, float)
    if p.shape != (3, 2) or not np.all(np.isfinite(p)):
        raise ValueError(f"positions has shape {p.shape}; need (3, 2) finite numbers")
    for name, value in (("mass", mass), ("roll_inertia", roll_inertia),
                        ("pitch_inertia", pitch_inertia)):
        if not (np.isfinite(value) and value > 0):
            raise ValueError(f"{name} = {value!r}; valid range is (0, inf)")
    A = np.column_stack([np.ones(3), p[:, 1], -p[:, 0]])
    if abs(np.linalg.det(A)) < 1e-12:
        raise ValueError("the three wheel centres are collinear")
    Ainv = np.linalg.inv(A)
    return Ainv.T @ np.diag([mass, roll_inertia, pitch_inertia]) @ Ainv


def heave_loads(inertia: np.ndarray, slope: np.ndarray, curvature: np.ndarray,
                rates: np.ndarray, accels: np.ndarray) -> np.ndarray:
    """``ΔN = K z̈`` with ``z̈_i = R'_i θ̈_i + R''_i θ̇_i²`` for (B, 3) wheel arrays, N.

    Args:
        inertia: K (3, 3) of :func:`contact_inertia`.
        slope: R'(φ_i) = x_c, m.
        curvature: R''(φ_i), m.
        rates: θ̇_i, rad/s.
        accels: θ̈_i, rad/s².
    """
    zdd = slope * accels + curvature * rates * rates
    return zdd @ np.asarray(inertia).T


def balance_loads(model: OmniHybrid, forces: np.ndarray, wheel_accels: np.ndarray,
                  geo: _Geometry | None = None) -> np.ndarray:
    """:meth:`OmniHybrid.normal_loads` for a batch of (B, 3) forces and wheel accelerations.

    With ``geo`` the supports are the contacts themselves, ``(L − y_σ) ê_i + x_c t_i``
    (the row's offset and the contact ahead of the axle move with the roller phase);
    without, the wheel centres' ``L ê_i``.
    """
    e, t = model.radial, model.drive_dirs
    nb = forces.shape[0]
    if geo is None:
        pos = np.broadcast_to(model.distance * e[:, :2], (nb, 3, 2))
    else:
        lever = model.distance - model.rollers.offsets[geo.modes]
        pos = lever[..., None] * e[:, :2] + geo.xc[..., None] * t[:, :2]
    dL = model.wheel_axial * wheel_accels @ -e[:, :2]
    r = model.radius
    A = np.stack([pos[..., 1], -pos[..., 0], np.ones((nb, 3))], axis=1)
    rhs = np.stack([dL[:, 0] - r * forces @ t[:, 1], dL[:, 1] + r * forces @ t[:, 0],
                    np.full(nb, model.mass * model.gravity)], axis=-1)
    return np.linalg.solve(A, rhs[..., None])[..., 0]
