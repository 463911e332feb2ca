"""The hybrid model's hand-over impact for many runs at once: :meth:`planar_impact`, stacked.

:func:`planar_impacts` is :meth:`~wmr_mujoco.robots.roller_wheels.omni_impacts.HybridImpacts.
planar_impact` (its equations and docstring) for B runs that hand over in the same step:
every small solve and product of the scalar map becomes one call on stacked ``(B, n, n)``
arrays, every scalar step one elementwise operation on ``(B,)`` arrays. Each run gets the
scalar map's floats: numpy's stacked ``solve`` calls LAPACK's ``gesv`` on each matrix, and
its stacked ``matmul`` the BLAS routine of each slice's shapes and layout (``gemv`` for a
matrix and a vector, ``dot`` for two vectors, ``gemm`` for two matrices), as the scalar
map's calls do; the elementwise steps are the scalar ones in the same order (IEEE, one
rounding each; a square of one number is C's ``pow``, as numpy computes it on a scalar).
``tests/robots/roller_wheels/test_omni_impact_batch.py`` checks the floats run by run.
What it saves is numpy's per-call cost: a hand-over step of omni3's families holds about
twenty runs, each ~60 small calls in the scalar map (~7x less per impact).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from wmr_mujoco.analytic.planar import wrap_angle

if TYPE_CHECKING:
    from wmr_mujoco.robots.roller_wheels.omni_hybrid import OmniHybrid


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``a[k] @ b[k]`` of (B, 3) rows: the vector-vector product of each pair, (B,)."""
    return (a[:, None, :] @ b[..., None])[:, 0, 0]


def _matvec(m: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``m[k] @ v[k]``: (B, n, p) with (B, p), (B, n)."""
    return (m @ v[..., None])[..., 0]


def _solve(m: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``np.linalg.solve(m[k], v[k])`` of each run's vector, (B, n)."""
    return np.linalg.solve(m, v[..., None])[..., 0]


def _planar_mass(model: OmniHybrid, H: np.ndarray, ks: np.ndarray) -> np.ndarray:
    """:meth:`OmniHybrid.planar_mass` of each run: ``P + (I_w Hᵀ) H + (I_r kᵀ) k``."""
    P = np.diag([model.mass, model.mass, model.inertia[2, 2]])
    return (P + (model.wheel_inertia * H.transpose(0, 2, 1)) @ H
            + (model.roller_axial * ks.transpose(0, 2, 1)) @ ks)


def _inplane(model: OmniHybrid, nu: np.ndarray, H_old: np.ndarray, H_new: np.ndarray,
             ks: np.ndarray, spins: np.ndarray) -> np.ndarray:
    """:meth:`HybridImpacts._inplane` of each run, (B, 3)."""
    nb = len(nu)
    Mw = model._inplane_metric
    w = np.concatenate([nu, _matvec(H_old, nu), spins], axis=1)
    A = np.zeros((nb, 6, 9))
    A[:, :3, :3], A[:, 3:, :3], A[:, :, 3:] = H_new, ks, -np.eye(6)
    if model.roller_axial == 0.0:  # massless rollers: no spin to project
        Mw, w, A = Mw[:6, :6], w[:, :6], A[:, :3, :6]
    Minv_At = np.linalg.solve(Mw, A.transpose(0, 2, 1))
    lam = _solve(A @ Minv_At, _matvec(A, w))
    return (w - _matvec(Minv_At, lam))[:, :3]


def _roller_terms(model: OmniHybrid, phi: np.ndarray
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``R(φ)``, ``x_c(φ)``, ``ρ(φ)`` of :class:`RollerGeometry` at each ``φ``, its floats.

    The scalar map evaluates them on one angle at a time, where numpy squares a number
    with the C library's ``pow`` (an array it squares by a product, which may differ in
    the last bit): the squares of ``h(φ)`` here are ``math.pow``'s.
    """
    g = model.rollers
    b, a = g.half_width, g.half_length
    c, s = np.cos(phi), np.sin(phi)
    c2 = np.array([math.pow(x, 2.0) for x in c.ravel().tolist()]).reshape(c.shape)
    s2 = np.array([math.pow(x, 2.0) for x in s.ravel().tolist()]).reshape(s.shape)
    h = np.sqrt(b * b * c2 + a * a * s2)
    return (g.axis_distance * c + h, -g.axis_distance * s + (a * a - b * b) * s * c / h,
            g.half_width ** 2 * c / h)


def _constraint_rows(model: OmniHybrid, modes: np.ndarray, thetas: np.ndarray) -> np.ndarray:
    """:meth:`HybridImpacts.constraint_rows` of each run, (B, 9, 12).

    Wheel by wheel as there: ``φ``, ``R(φ)``, ``x_c(φ)``, ``ρ(φ)``, the contact point
    ``p`` and the rows ``(d, −d·[p]ₓ, coefficient)`` of each direction ``d``; the products
    ``(−d) @ [p]ₓ`` one vector-matrix product per row.
    """
    g = model.rollers
    phi = wrap_angle(g.angles[modes] + thetas - math.pi)
    rolling, ahead, radius = _roller_terms(model, phi)
    p = (model.distance * model.radial + ahead[..., None] * model.drive_dirs
         - g.offsets[modes][..., None] * model.radial)
    p[..., 2] -= rolling  # − (0, 0, R): the other entries minus 0.0 are themselves
    zero = np.zeros(phi.shape)
    skew = np.stack([np.stack([zero, -p[..., 2], p[..., 1]], -1),
                     np.stack([p[..., 2], zero, -p[..., 0]], -1),
                     np.stack([-p[..., 1], p[..., 0], zero], -1)], -2)  # (B, 3, 3, 3)
    dirs = model.contact_dirs
    lever = (-dirs[None, :, :, None, :] @ skew[:, :, None])[..., 0, :]  # (B, 3, 3, 3)
    nb = len(modes)
    A = np.zeros((nb, 3, 3, 12))  # run, wheel, row, column
    A[..., :3] = dirs
    A[..., 3:6] = lever
    wheel = np.arange(3)
    A[:, wheel, 0, 6 + wheel] = -rolling
    A[:, wheel, 1, 6 + wheel] = -ahead
    A[:, wheel, 2, 9 + wheel] = -radius
    return A.reshape(nb, 9, 12)


def _vertical_impulses(model: OmniHybrid, nu: np.ndarray, old: np.ndarray, new: np.ndarray,
                       thetas: np.ndarray, spins: np.ndarray) -> np.ndarray:
    """:meth:`HybridImpacts.vertical_impulses` of each run, (B, 3).

    The constraint rows of :func:`_constraint_rows`; the solves stacked.
    """
    a_old, a_new = _constraint_rows(model, old, thetas), _constraint_rows(model, new, thetas)
    known, unknown = [0, 1, 5], [2, 3, 4, 6, 7, 8, 9, 10, 11]
    # lift(ν, σ_old, θ, β̇): q with q[known] = ν, the constrained rest, β̇ the spins
    # Each product's slices are laid out as the scalar map's operands (BLAS picks its
    # kernel by the layout): ``-A[:, known]`` is column-major there, ``Ar`` row-major.
    known_cols = np.ascontiguousarray(-a_old[:, :, known].transpose(0, 2, 1))
    sol = _solve(a_old[:, :, unknown], _matvec(known_cols.transpose(0, 2, 1), nu))
    q = np.zeros((len(nu), 12))
    q[:, known], q[:, unknown] = nu, sol
    q[:, 9:] = spins
    cols, rows = model._massive(a_new[0])
    Ar = np.ascontiguousarray(a_new[:, rows][:, :, cols])
    impulse = _solve(Ar @ model._full_mass_inv(cols.size) @ Ar.transpose(0, 2, 1),
                     _matvec(Ar, q[:, cols]))
    xc = -a_new[:, [1, 4, 7], [6, 7, 8]]
    return xc * impulse[:, 1::3 if cols.size == 12 else 2]


def _crossing_time(window: np.ndarray, rate: np.ndarray, accel: np.ndarray) -> np.ndarray:
    """:func:`~wmr_mujoco.robots.roller_wheels.omni_impacts.crossing_time` elementwise."""
    w, a = np.abs(rate), np.abs(accel)
    den = w + np.sqrt(w * w + 2.0 * a * window)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(den > 0.0, 2.0 * window / den, math.inf)


def _overlap_impulse(model: OmniHybrid, nu: np.ndarray, new: np.ndarray, thetas: np.ndarray,
                     wheel: int, rate: np.ndarray, accel: np.ndarray) -> np.ndarray:
    """:meth:`HybridImpacts.overlap_impulse` of wheel ``wheel`` in each run, (B,)."""
    g = model.rollers
    m = new[:, wheel]
    phi = wrap_angle(g.angles[m] + thetas[:, wheel] - math.pi)
    window = model.penetration / np.maximum(np.abs(_roller_terms(model, phi)[1]), 1e-12)
    e = np.abs(g.offsets[m])
    load = model.mass * model.gravity / 3.0
    force = np.full(len(nu), model.friction * load / 4.0)
    if model.contact_timeconst > 0.0:
        damped = load / model.gravity * 2.0 / model.contact_timeconst * e * np.abs(nu[:, 2])
        force = np.where(damped < force, damped, force)  # Python's min(force, damped)
    out = 2.0 * e * force * _crossing_time(window, rate, accel)
    return np.where((rate == 0.0) & (accel == 0.0), 0.0, out)


def _remove_energy(nu: np.ndarray, h: np.ndarray, m_red: np.ndarray, energy: float
                   ) -> np.ndarray:
    """:meth:`HybridImpacts.remove_energy` of each run along its row ``h`` (B, 3)."""
    rate = _dot(h, nu)
    c = _dot(h, _solve(m_red, h))
    disc = rate * rate - 2.0 * c * energy
    root = np.copysign(np.sqrt(np.maximum(disc, 0.0)), rate)
    j = np.where(disc > 0, (rate - root) / c, rate / c)
    return nu - _solve(m_red, h * j[:, None])


def planar_impacts(model: OmniHybrid, nu: np.ndarray, old: np.ndarray, new: np.ndarray,
                   thetas: np.ndarray, spins: np.ndarray, wheel_accels: np.ndarray | None = None,
                   rows: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None = None
                   ) -> tuple[np.ndarray, np.ndarray]:
    """:meth:`HybridImpacts.planar_impact` of B runs: ``(ν⁺ (B, 3), ΔT (B,))``.

    Args:
        model: the platform.
        nu: (B, 3) twists before the hand-over.
        old: (B, 3) integer modes before the hand-over.
        new: (B, 3) integer modes after it.
        thetas: (B, 3) wheel angles.
        spins: (B, 3) the entering rollers' spins.
        wheel_accels: (B, 3) the wheels' θ̈ of the continuous phase (None: zero).
        rows: ``(H(σ_old), H(σ_new), k(σ_old), k(σ_new))`` (B, 3, 3) at ``thetas`` if the
            caller has them (the integrator's geometry: the same floats), else made here.
    """
    from wmr_mujoco.robots.roller_wheels.omni_batch import _geometry

    nu, thetas, spins = (np.asarray(a, float) for a in (nu, thetas, spins))
    old, new = np.asarray(old, int), np.asarray(new, int)
    accels = np.zeros_like(nu) if wheel_accels is None else np.asarray(wheel_accels, float)
    if rows is None:
        H_old = np.stack([model.jacobian(tuple(o)) for o in old.tolist()])
        H_new = np.stack([model.jacobian(tuple(n)) for n in new.tolist()])
        ks_old, ks = _geometry(model, thetas, old).ks, _geometry(model, thetas, new).ks
    else:
        H_old, H_new, ks_old, ks = rows
    nu_plus = _inplane(model, nu, H_old, H_new, ks, spins)
    J = _vertical_impulses(model, nu, old, new, thetas, spins)
    m_red = _planar_mass(model, H_new, ks)
    nu_plus = nu_plus + _solve(m_red, _matvec(H_new.transpose(0, 2, 1), J))
    if model.penetration > 0:
        for i in range(3):
            runs = np.flatnonzero(new[:, i] != old[:, i])
            if not runs.size:
                continue
            sub, m_sub, h = nu_plus[runs], m_red[runs], H_new[runs, i]
            sub = _remove_energy(sub, h, m_sub, model.handover_dissipation)
            rate = _dot(h, sub)
            impulse = _overlap_impulse(model, sub, new[runs], thetas[runs], i, rate,
                                       accels[runs, i])
            kick = np.zeros((runs.size, 3))
            kick[:, 2] = impulse
            dnu = _solve(m_sub, kick)
            big = np.abs(dnu[:, 2]) >= np.abs(sub[:, 2])  # friction stops, never reverses
            dnu[big] *= (np.abs(sub[big, 2]) / np.maximum(np.abs(dnu[big, 2]), 1e-300))[:, None]
            nu_plus[runs] = sub - np.copysign(1.0, sub[:, 2])[:, None] * dnu
    m_old = _planar_mass(model, H_old, ks_old)
    kinetic = _dot((0.5 * nu[:, None, :] @ m_old)[:, 0], nu)  # kinetic_energy(ν, σ_old)
    kn = _matvec(ks, nu)
    lost = (kinetic + 0.5 * model.roller_axial * (_dot(spins, spins) - _dot(kn, kn))
            - _dot((0.5 * nu_plus[:, None, :] @ m_red)[:, 0], nu_plus))
    return nu_plus, lost
