"""Traction-limited acceleration of a platform on free-roller wheels (Swedish/mecanum).

A wheel whose contact roller turns freely cannot push along the roller's rolling
direction; it pushes the chassis only along the roller axis ``e_i = (cos(β_i+γ_i),
sin(β_i+γ_i))`` (body frame), by a force ``F_i`` with ``|F_i| ≤ μ N_i`` (Coulomb). The
generalised force on the body twist ``ν = (u, v, r)`` is

    Q = Σ_i F_i g_i,     g_i = (e_i, p_i × e_i),

with ``p_i`` the contact's position. A step command ``ν_cmd`` is reached fastest, along
its own direction, at the largest ``s`` for which ``M ν_cmd s = Σ F_i g_i`` has forces
within the friction bounds (a linear programme), ``M = diag(m, m, I_z)``; the servos turn
the wheels themselves, so the wheels' spin inertia takes no traction. The chassis then
reaches ``ν_cmd`` after ``T = 1/s`` and, compared with the instant step of the ideal
kinematics, falls behind by ``ν_cmd T / 2`` for good: a position lag ``|(u, v)| T / 2``
and a heading lag ``|r| T / 2``. (Coriolis terms over the short transient are neglected.)

Closed forms for ``mecanum4`` (γ = ±45°, ``N_i = m g / 4``): along x or y
``a = μ g / √2``; along a diagonal only two wheels push, ``a = μ g / 2``; turning on the
spot, ``α = μ m g (a + w) / (√2 I_z)``.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import linprog

from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok


def traction_directions(layout: ok.WheelLayout) -> np.ndarray:
    """(3, n) columns ``g_i = (e_i, p_i × e_i)``: what a unit roller-axis force does."""
    ang = layout.drive_angles + layout.roller_angles
    e = np.stack([np.cos(ang), np.sin(ang)])
    p = layout.positions.T
    return np.vstack([e, p[0] * e[1] - p[1] * e[0]])


def acceleration_time(layout: ok.WheelLayout, mass: float, yaw_inertia: float,
                      normal_forces: np.ndarray, friction: float,
                      twist: np.ndarray) -> float:
    """Least time ``T`` to reach ``twist`` from rest at a uniform traction-limited rate.

    Args:
        layout: wheel geometry (body frame).
        mass: total mass m, kg.
        yaw_inertia: total yaw inertia about the centre, kg·m².
        normal_forces: (n,) wheel loads N_i, N.
        friction: Coulomb coefficient μ.
        twist: (3,) commanded body twist ``(u, v, r)``, m/s and rad/s.

    Returns:
        ``T = 1 / s_max`` in seconds (0 for a zero twist).

    Raises:
        ValueError: non-positive mass, inertia, loads or friction; or the traction
            cannot accelerate along ``twist`` at all.
    """
    for name, value in (("mass", mass), ("yaw_inertia", yaw_inertia), ("friction", friction)):
        if not (np.isfinite(value) and value > 0):
            raise ValueError(f"{name} = {value!r}; must be finite and > 0")
    loads = np.asarray(normal_forces, float)
    if loads.shape != (layout.n,) or not np.all(loads > 0):
        raise ValueError(f"normal_forces = {normal_forces!r}; need {layout.n} loads > 0")
    nu = np.asarray(twist, float)
    if not np.any(nu):
        return 0.0
    g = traction_directions(layout)
    demand = np.array([mass, mass, yaw_inertia]) * nu
    # Variables (F_1..F_n, s): maximise s subject to G F − s M ν = 0, |F_i| ≤ μ N_i.
    a_eq = np.hstack([g, -demand[:, None]])
    bounds = [(-friction * n, friction * n) for n in loads] + [(0.0, None)]
    c = np.zeros(layout.n + 1)
    c[-1] = -1.0
    res = linprog(c, A_eq=a_eq, b_eq=np.zeros(3), bounds=bounds, method="highs")
    if res.status != 0 or res.x[-1] <= 0.0:
        raise ValueError(f"twist = {twist!r}: the roller-axis forces cannot accelerate "
                         "along it")
    return float(1.0 / res.x[-1])
