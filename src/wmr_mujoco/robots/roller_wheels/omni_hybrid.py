"""Hybrid dynamics of a three-omni-wheel platform with two staggered roller rows.

Derivations: ``docs/omni-dynamics.md``. Symbols (body frame, z up, centre at wheel-centre
height): wheel i at ``c_i = L ê_i``, drive direction ``t_i = ẑ × ê_i``, axle (hinge axis,
positive wheel rate) ``a_i = −ê_i``. Roller k of a wheel sits at angle ``ζ_k`` around the
axle and axial offset ``y_k = ±e``; at wheel angle θ its angle past the bottom is
``φ_k = wrap(ζ_k + θ − π)`` (φ > 0: behind the axle). The roller in contact (mode σ_i) is
the lowest one: ``σ_i = argmin_k |φ_k|``.

Ellipsoid roller (semi-axes b, b, a; axis at d from the axle) at angle φ::

    h(φ) = √(b² cos²φ + a² sin²φ)                 support along the floor normal
    R(φ) = d cos φ + h(φ)                          axle height over the contact
    x_c(φ) = R'(φ) = −d sin φ + (a² − b²) sin φ cos φ / h    contact ahead of the axle
    ρ(φ) = b² cos φ / h(φ)                         contact distance from the roller axis

Continuous phase (mode σ fixed), Lagrange–d'Alembert with constraints
``θ̇ = H(σ) ν`` and roller spin ``β̇ = k(φ)ᵀ ν``::

    (P + I_w HᵀH + I_r Σ k_i k_iᵀ) ν̇ + c(ν) + I_r Σ k_i (∂k_i/∂φ θ̇_i)ᵀ ν = Hᵀ τ
    P = diag(M, M, I_z),   c(ν) = r (−M v, M u, 0),
    H_i = (t_i,x, t_i,y, L − y_σ) / r,   k_i = (a_i,x, a_i,y, x_c(φ_i)) / ρ(φ_i)

Switch (σ_i changes): plastic impact onto the new contact's constraints in the
12-dimensional velocity ``q̇ = (V, Ω, θ̇, β̇)`` with mass matrix 𝕄::

    q̇⁺ = q̇⁻ − 𝕄⁻¹Aᵀ (A𝕄⁻¹Aᵀ)⁻¹ A q̇⁻,      ΔT = ½ (A q̇⁻)ᵀ (A𝕄⁻¹Aᵀ)⁻¹ (A q̇⁻) ≥ 0

Drive laws: torque (``τ = u``) or rate servo (``τ = clip(k_v (u − θ̇), ±τ_max)``).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from wmr_mujoco.analytic.checks import as_array, positive
from wmr_mujoco.robots.roller_wheels.omni_batch import (
    HybridRun,
    _accelerations,
    _geometry,
    _normal_loads,
    simulate,
    simulate_batch,
)
from wmr_mujoco.robots.roller_wheels.omni_impacts import _UP, HybridImpacts
from wmr_mujoco.robots.roller_wheels.omni_rates import kinetic_energies, rolling_rates
from wmr_mujoco.robots.roller_wheels.roller_geometry import Drive, RollerGeometry, _finite

__all__ = ["Drive", "HybridRun", "OmniHybrid", "RollerGeometry", "kinetic_energies",
           "rolling_rates", "simulate", "simulate_batch"]


@dataclass(frozen=True)
class OmniHybrid(HybridImpacts):
    """Three-wheel omni platform with mode-dependent contact rows.

    Attributes:
        mass: total mass M, kg.
        inertia: composite 3×3 inertia about the centre, body frame, kg·m².
        wheel_axial: each wheel subtree's inertia about its axle (no armature), kg·m².
        wheel_armature: reflected rotor inertia on each wheel hinge, kg·m².
        roller_axial: each roller's inertia about its own axis (with armature), kg·m².
        radius: r, nominal wheel radius (used in H), m.
        distance: L, centre to wheel centres, m.
        rollers: roller geometry (same for every wheel).
        wheel_angles: α_i of the wheels, rad.
        gravity: g, m/s².
        penetration: δ, static penetration of a loaded contact (0 for rigid contacts), m.
            A compliant contact stores ``½ N δ`` (N = M g / 3); a hand-over moves the load
            to an unloaded contact and the stored energy is dissipated (see the docs).
        friction: μ, Coulomb friction of the roller–floor contact (traction limit μ N).
        contact_timeconst: t_c of the soft contact (solref), s; its tangential rows damp a
            slip s with the force ``(N/g)(2/t_c) s`` below the Coulomb limit (0: Coulomb).
        handover_relaxation: ρ, the share of a hand-over's velocity jump the soft contact
            has not made after one simulation step (0: at once, the rigid impact;
            :func:`simulate_batch`'s ``relax``; a property of the contact at the step of
            the simulation it models, ``docs/omni-dynamics.md`` § 5).
    """

    mass: float
    inertia: np.ndarray
    wheel_axial: float
    wheel_armature: float
    roller_axial: float
    radius: float
    distance: float
    rollers: RollerGeometry
    wheel_angles: np.ndarray = field(
        default_factory=lambda: 2.0 * np.pi * np.arange(3) / 3.0)
    gravity: float = 9.81
    penetration: float = 0.0
    friction: float = 1.0
    contact_timeconst: float = 0.0
    handover_relaxation: float = 0.0

    def __post_init__(self) -> None:
        positive("mass", self.mass)
        positive("wheel_axial", self.wheel_axial)
        positive("radius", self.radius)
        positive("distance", self.distance)
        positive("gravity", self.gravity)
        positive("friction", self.friction)
        for name in ("wheel_armature", "roller_axial", "penetration"):
            if _finite(name, getattr(self, name)) < 0:
                raise ValueError(f"{name} = {getattr(self, name)!r}; valid range is [0, inf)")
        if not -1.0 < _finite("handover_relaxation", self.handover_relaxation) < 1.0:
            raise ValueError(f"handover_relaxation = {self.handover_relaxation!r}; valid "
                             "range is (-1, 1)")
        inertia = as_array("inertia", self.inertia, (3, 3))
        if np.any(np.linalg.eigvalsh(0.5 * (inertia + inertia.T)) <= 0):
            raise ValueError("inertia must be symmetric positive definite")
        alpha = as_array("wheel_angles", self.wheel_angles, (3,))
        object.__setattr__(self, "inertia", inertia.copy())
        object.__setattr__(self, "wheel_angles", alpha.copy())

    # --- geometry -------------------------------------------------------------------
    @functools.cached_property
    def radial(self) -> np.ndarray:
        """ê_i (3, 3) rows, body frame."""
        a = self.wheel_angles
        return np.stack([np.cos(a), np.sin(a), 0.0 * a], axis=1)

    @functools.cached_property
    def drive_dirs(self) -> np.ndarray:
        """t_i = ẑ × ê_i."""
        a = self.wheel_angles
        return np.stack([-np.sin(a), np.cos(a), 0.0 * a], axis=1)

    @functools.cached_property
    def contact_dirs(self) -> np.ndarray:
        """Each wheel's contact-row directions ``(t_i, ẑ, −ê_i)`` (3 wheels, 3 rows, 3)."""
        dirs = np.stack([self.drive_dirs, np.broadcast_to(_UP, (3, 3)), -self.radial], 1)
        dirs.setflags(write=False)
        return dirs

    @functools.cached_property
    def roller_gap(self) -> float:
        """``s``: the least angle between two rollers of a wheel, rad."""
        ring = np.sort(np.remainder(self.rollers.angles, 2.0 * math.pi))
        return float(np.diff(ring, append=ring[0] + 2.0 * math.pi).min())

    def modes(self, thetas: np.ndarray) -> tuple[int, int, int]:
        """σ_i: roller in contact on each wheel."""
        return tuple(self.rollers.lowest(float(t)) for t in thetas)

    def contact_point(self, i: int, roller: int, theta: float) -> np.ndarray:
        """``p = c_i + x_c t_i + y_k a_i − R ẑ`` (body frame)."""
        phi = float(self.rollers.phases(theta)[roller])
        g = self.rollers
        return (self.distance * self.radial[i] + g.contact_ahead(phi) * self.drive_dirs[i]
                - g.offsets[roller] * self.radial[i]
                - np.array([0.0, 0.0, g.rolling_radius(phi)]))

    def jacobian(self, modes: tuple[int, ...]) -> np.ndarray:
        """``H(σ)``: row i = (t_i,x, t_i,y, L − y_σi) / r (read-only, one per mode σ)."""
        key = tuple(int(m) for m in modes)
        H = self._jacobians.get(key)
        if H is None:
            t = self.drive_dirs
            lever = self.distance - self.rollers.offsets[list(key)]
            H = np.column_stack([t[:, 0], t[:, 1], lever]) / self.radius
            H.setflags(write=False)
            self._jacobians[key] = H
        return H

    @functools.cached_property
    def _jacobians(self) -> dict[tuple[int, ...], np.ndarray]:
        return {}

    def roller_rows(self, modes: tuple[int, ...], thetas: np.ndarray
                    ) -> tuple[np.ndarray, np.ndarray]:
        """``k_i`` (β̇_i = k_iᵀ ν) and ``∂k_i/∂φ`` (closed forms, see :func:`_geometry`)."""
        geo = _geometry(self, np.asarray(thetas, float)[None], np.asarray(modes)[None])
        return geo.ks[0], geo.dks[0]

    # --- continuous phase ----------------------------------------------------------------
    @property
    def wheel_inertia(self) -> float:
        """I_w = wheel subtree axial inertia + armature."""
        return self.wheel_axial + self.wheel_armature

    def planar_mass(self, modes: tuple[int, ...], thetas: np.ndarray,
                    ks: np.ndarray | None = None) -> np.ndarray:
        """``P + I_w HᵀH + I_r Σ k kᵀ`` (``ks``: the rows ``k_i`` where already known)."""
        H = self.jacobian(modes)
        if ks is None:
            ks, _ = self.roller_rows(modes, thetas)
        P = np.diag([self.mass, self.mass, self.inertia[2, 2]])
        return P + self.wheel_inertia * H.T @ H + self.roller_axial * ks.T @ ks

    def velocity_term(self, nu: np.ndarray) -> np.ndarray:
        """``c(ν) = r (−M v, M u, 0)``: only the platform's momentum turns with the frame."""
        u, v, r = nu
        return np.array([-self.mass * r * v, self.mass * r * u, 0.0])

    def body_acceleration(self, nu: np.ndarray, thetas: np.ndarray, modes: tuple[int, ...],
                          torques: np.ndarray) -> np.ndarray:
        """``ν̇`` of the continuous phase in mode σ (module docstring), every wheel rolling."""
        none_slipping = np.zeros(3, dtype=bool)
        return self.accelerations(nu, thetas, modes, torques, none_slipping, np.zeros(3))[0]

    def accelerations(self, nu: np.ndarray, thetas: np.ndarray, modes: tuple[int, ...],
                      torques: np.ndarray, slipping: np.ndarray, slip_forces: np.ndarray,
                      loads: np.ndarray | None = None
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(ν̇, θ̈, F_t)`` with some wheels slipping (their traction ``slip_forces`` given).

        With ``loads`` N, each wheel also feels the moment of its normal force about the
        axle, ``−N_i x_c(φ_i)`` (the contact is ``x_c`` ahead of the axle): the
        generalised force of the platform's weight as the wheel rolls over the roller's
        arc, ``−∂(M g z)/∂θ_i`` with ``z = Σ R(φ_i)/3``.

        Rolling wheels: ``θ̈_i = H_i ν̇`` and ``F_t,i = (τ_i − I_w H_i ν̇)/r``; slipping
        wheels: ``I_w θ̈_i = τ_i − r F_t,i``. Platform::

            (P + I_r Σ k kᵀ + I_w Σ_rolling H_iᵀH_i) ν̇ = −c(ν) − roller term
                + Σ_rolling H_iᵀ τ_i + Σ_slipping r H_iᵀ F_t,i
        """
        thetas = np.asarray(thetas, float)[None]
        geo = _geometry(self, thetas, np.asarray(modes)[None])
        nudot, thdd, forces = _accelerations(
            self, geo, np.asarray(nu, float)[None], np.asarray(torques, float)[None],
            np.asarray(slipping, bool)[None], np.asarray(slip_forces, float)[None],
            None if loads is None else np.asarray(loads, float)[None])
        return nudot[0], thdd[0], forces[0]

    def normal_loads(self, forces: np.ndarray, wheel_accels: np.ndarray) -> np.ndarray:
        """Normal loads N (N) from the robot's balance about its centre of mass.

        Centre of mass at wheel-centre height, contacts r below at ``L ê_i``::

            Σ N_i = M g,   Σ p_i × (N_i ẑ + F_t,i t_i) = Σ I_ax θ̈_i a_i   (horizontal)

        (the spinning wheels' angular momentum; the armature carries none).
        """
        return _normal_loads(self, np.asarray(forces, float)[None],
                             np.asarray(wheel_accels, float)[None])[0]

    def stick(self, nu: np.ndarray, rates: np.ndarray, modes: tuple[int, ...],
              thetas: np.ndarray, rolling: np.ndarray) -> np.ndarray:
        """Plastic re-stick of slipping wheels; returns ``ν⁺``.

        Projects ``(ν, θ̇)`` onto ``θ̇_i = H_i ν`` (the ``rolling`` wheels) in the metric
        ``blockdiag(P + I_r Σ kkᵀ, I_w 1)``.
        """
        H = self.jacobian(modes)
        ks, _ = self.roller_rows(modes, thetas)
        Mw = np.zeros((6, 6))
        Mw[:3, :3] = (np.diag([self.mass, self.mass, self.inertia[2, 2]])
                      + self.roller_axial * ks.T @ ks)
        Mw[3:, 3:] = self.wheel_inertia * np.eye(3)
        A = np.hstack([H, -np.eye(3)])[rolling]
        w = np.concatenate([nu, rates])
        Minv_At = np.linalg.solve(Mw, A.T)
        return (w - Minv_At @ np.linalg.solve(A @ Minv_At, A @ w))[:3]

    def kinetic_energy(self, nu: np.ndarray, modes: tuple[int, ...],
                       thetas: np.ndarray) -> float:
        """``½ νᵀ (P + I_w HᵀH + I_r Σ k kᵀ) ν``."""
        return float(0.5 * nu @ self.planar_mass(modes, thetas) @ nu)
