"""The impact maps of the omni platform's hybrid model: roller hand-overs and re-sticks.

Switch (σ_i changes): plastic impact onto the new contact's constraints in the
12-dimensional velocity ``q̇ = (V, Ω, θ̇, β̇)`` with mass matrix 𝕄::

    q̇⁺ = q̇⁻ − 𝕄⁻¹Aᵀ (A𝕄⁻¹Aᵀ)⁻¹ A q̇⁻,      ΔT = ½ (A q̇⁻)ᵀ (A𝕄⁻¹Aᵀ)⁻¹ (A q̇⁻) ≥ 0

(derivations: ``docs/omni-dynamics.md``). :class:`HybridImpacts` is the part of
:class:`~wmr_mujoco.robots.roller_wheels.omni_hybrid.OmniHybrid` that holds these maps; what it
reads of the platform (fields and geometry) is the protocol :class:`OmniPlatform`.
"""

from __future__ import annotations

import functools
import math
from typing import TYPE_CHECKING, Protocol

import numpy as np

from wmr_mujoco.robots.roller_wheels.roller_geometry import RollerGeometry


def crossing_time(window: float, rate: float, accel: float) -> float:
    """Time a wheel at rate ``θ̇`` and acceleration ``θ̈`` takes to turn through ``window``.

    ``Δφ = |θ̇| t + ½ |θ̈| t²`` solved for t (the rate's and the acceleration's magnitudes:
    a wheel slowing down inside the window turns back and leaves it after at most the
    same time, so this is the time to the first exit, within a factor 2 of the whole
    stay)::

        t = 2 Δφ / (|θ̇| + √(θ̇² + 2 |θ̈| Δφ))

    ``Δφ/|θ̇|`` for ``θ̈ = 0``; ``√(2 Δφ/|θ̈|)`` for ``θ̇ = 0``; inf for both zero.

    Raises:
        ValueError: a negative or non-finite window.
    """
    if not (math.isfinite(window) and window >= 0.0):
        raise ValueError(f"window = {window!r} rad; valid range is [0, inf)")
    w, a = abs(float(rate)), abs(float(accel))
    den = w + math.sqrt(w * w + 2.0 * a * window)
    return 2.0 * window / den if den > 0.0 else math.inf


class OmniPlatform(Protocol):
    """What the impact maps read of the platform they are mixed into (``OmniHybrid``)."""

    @property
    def mass(self) -> float:
        """M, kg."""

    @property
    def inertia(self) -> np.ndarray:
        """Composite 3×3 inertia about the centre, body frame, kg·m²."""

    @property
    def wheel_axial(self) -> float:
        """I_ax: a wheel subtree's inertia about its axle (no armature), kg·m²."""

    @property
    def wheel_inertia(self) -> float:
        """I_w = I_ax + armature, kg·m²."""

    @property
    def roller_axial(self) -> float:
        """I_r: a roller's inertia about its own axis, kg·m²."""

    @property
    def rollers(self) -> RollerGeometry:
        """Roller geometry (same for every wheel)."""

    @property
    def gravity(self) -> float:
        """g, m/s²."""

    @property
    def penetration(self) -> float:
        """δ, static penetration of a loaded contact, m."""

    @property
    def friction(self) -> float:
        """μ of the roller–floor contact."""

    @property
    def contact_timeconst(self) -> float:
        """t_c of the soft contact, s (0: Coulomb)."""

    @property
    def radial(self) -> np.ndarray:
        """ê_i (3, 3) rows, body frame."""

    @property
    def drive_dirs(self) -> np.ndarray:
        """t_i = ẑ × ê_i (3, 3) rows."""

    def contact_point(self, i: int, roller: int, theta: float) -> np.ndarray:
        """Contact point of wheel i's roller at wheel angle θ (body frame)."""

    def jacobian(self, modes: tuple[int, ...]) -> np.ndarray:
        """``H(σ)``: θ̇ = H ν."""

    def roller_rows(self, modes: tuple[int, ...], thetas: np.ndarray
                    ) -> tuple[np.ndarray, np.ndarray]:
        """``k_i`` (β̇_i = k_iᵀ ν) and ``∂k_i/∂φ``."""

    def planar_mass(self, modes: tuple[int, ...], thetas: np.ndarray) -> np.ndarray:
        """``P + I_w HᵀH + I_r Σ k kᵀ``."""

    def kinetic_energy(self, nu: np.ndarray, modes: tuple[int, ...],
                       thetas: np.ndarray) -> float:
        """``½ νᵀ (P + I_w HᵀH + I_r Σ k kᵀ) ν``."""


# The mixin's methods read the host's members: type checkers see the protocol as its base;
# at run time it has none (a protocol's properties would shadow the host's fields).
#: ẑ, the floor normal (body frame; read-only).
_UP = np.array([0.0, 0.0, 1.0])
_UP.setflags(write=False)

if TYPE_CHECKING:
    _Host = OmniPlatform
else:
    _Host = object


class HybridImpacts(_Host):
    """Impact maps of the hybrid model, mixed into a class that is an :class:`OmniPlatform`."""

    # --- impact ----------------------------------------------------------------------------
    @functools.cached_property
    def _full_mass(self) -> np.ndarray:
        Mq = self._build_full_mass()
        Mq.setflags(write=False)
        return Mq

    @functools.cached_property
    def _full_mass_invs(self) -> dict[int, np.ndarray]:
        return {}

    def _full_mass_inv(self, n: int) -> np.ndarray:
        """Inverse of the leading n×n block of 𝕄 (n = 12, or 9 with massless rollers)."""
        if n not in self._full_mass_invs:
            self._full_mass_invs[n] = np.linalg.inv(self._full_mass[:n, :n])
        return self._full_mass_invs[n]

    def full_mass(self) -> np.ndarray:
        """𝕄 of ``q̇ = (V, Ω, θ̇, β̇)``: the wheel spin couples to Ω through I_ax a_i."""
        return self._full_mass.copy()

    def _build_full_mass(self) -> np.ndarray:
        Mq = np.zeros((12, 12))
        Mq[:3, :3] = self.mass * np.eye(3)
        Mq[3:6, 3:6] = self.inertia
        a = -self.radial
        for i in range(3):
            Mq[3:6, 6 + i] = Mq[6 + i, 3:6] = self.wheel_axial * a[i]
            Mq[6 + i, 6 + i] = self.wheel_inertia
            Mq[9 + i, 9 + i] = self.roller_axial
        return Mq

    def constraint_rows(self, modes: tuple[int, ...], thetas: np.ndarray) -> np.ndarray:
        """Constraint rows A (9×12) of mode σ: contact velocity along t_i, ẑ and a_i.

        ``t·(V + Ω×p) − R θ̇ = 0``, ``ẑ·(V + Ω×p) − x_c θ̇ = 0``,
        ``a·(V + Ω×p) − ρ β̇ = 0`` (the roller takes the slide along the axle).
        """
        A = np.zeros((9, 12))
        memo = self._wheel_rows
        if len(memo) > 24:  # an impact's old and new modes share the unchanged wheels' rows
            memo.clear()
        for i, (m, th) in enumerate(zip(modes, thetas, strict=True)):
            key = (i, int(m), float(th))
            rows = memo.get(key)
            if rows is None:
                rows = memo[key] = self._wheel_constraint_rows(i, int(m), float(th))
            A[3 * i:3 * i + 3] = rows
        return A

    @functools.cached_property
    def _wheel_rows(self) -> dict[tuple[int, int, float], np.ndarray]:
        return {}

    def _wheel_constraint_rows(self, i: int, m: int, th: float) -> np.ndarray:
        """Wheel ``i``'s three rows of :meth:`constraint_rows` (roller ``m``, angle ``th``)."""
        A = np.zeros((3, 12))
        g = self.rollers
        phi = float(g.phases(float(th))[m])
        rolling, ahead = g.rolling_radius(phi), g.contact_ahead(phi)
        # contact_point(i, m, θ), its terms evaluated once
        p = (self.distance * self.radial[i] + ahead * self.drive_dirs[i]
             - g.offsets[m] * self.radial[i] - np.array([0.0, 0.0, rolling]))
        skew_p = np.array([[0, -p[2], p[1]], [p[2], 0, -p[0]], [-p[1], p[0], 0]])
        for row, (d, coef, col) in enumerate((
                (self.drive_dirs[i], -rolling, 6 + i),
                (_UP, -ahead, 6 + i),
                (-self.radial[i], -g.contact_radius(phi), 9 + i))):
            A[row, :3] = d
            A[row, 3:6] = -d @ skew_p  # d·(Ω × p) = −d·(p × Ω)
            A[row, col] = coef
        A.setflags(write=False)
        return A

    def lift(self, nu: np.ndarray, modes: tuple[int, ...], thetas: np.ndarray,
             roller_rates: np.ndarray | None = None) -> np.ndarray:
        """Full velocity in mode σ: the q̇ with planar part ν that satisfies A q̇ = 0.

        If ``roller_rates`` is given those β̇ replace the constrained ones (a roller that
        has just come into contact still turns at its old rate).
        """
        A = self.constraint_rows(modes, thetas)
        # Unknowns: V_z, Ω_x, Ω_y, θ̇ (3), β̇ (3); knowns: u, v, r.
        known = [0, 1, 5]
        unknown = [2, 3, 4, 6, 7, 8, 9, 10, 11]
        sol = np.linalg.solve(A[:, unknown], -A[:, known] @ nu)
        q = np.zeros(12)
        q[known] = nu
        q[unknown] = sol
        if roller_rates is not None:
            q[9:] = roller_rates
        return q

    def impact(self, q_minus: np.ndarray, modes: tuple[int, ...], thetas: np.ndarray
               ) -> tuple[np.ndarray, float]:
        """Plastic impact onto mode σ's constraints: ``(q̇⁺, ΔT)``, ΔT ≥ 0 the energy lost."""
        Mq = self.full_mass()
        A = self.constraint_rows(modes, thetas)
        cols, rows = self._massive(A)
        Minv_At = np.zeros((12, rows.size))
        Minv_At[cols] = np.linalg.solve(Mq[np.ix_(cols, cols)], A[np.ix_(rows, cols)].T)
        gap = A[rows] @ q_minus
        impulse = np.linalg.solve(A[rows] @ Minv_At, gap)
        q_plus = q_minus - Minv_At @ impulse
        if cols.size < 12:  # massless rollers follow their constraint
            q_plus[9:] = self.lift(q_plus[[0, 1, 5]], modes, thetas)[9:]
        return q_plus, float(0.5 * gap @ impulse)

    def _massive(self, A: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Velocity columns with inertia and the constraint rows acting on them."""
        if self.roller_axial > 0.0:
            return np.arange(12), np.arange(A.shape[0])
        return np.arange(9), np.array([r for r in range(A.shape[0]) if r % 3 != 2])

    def inplane_impact(self, nu: np.ndarray, old: tuple[int, ...], new: tuple[int, ...],
                       thetas: np.ndarray, spins: np.ndarray) -> np.ndarray:
        """Projection of ``w = (ν, θ̇, β̇)`` onto ``θ̇ = H_new ν, β̇ = K_new ν``.

        Metric ``blockdiag(P, I_w 1, I_r 1)``; before: ``θ̇ = H_old ν`` and ``β̇`` = the
        contacting rollers' spins ``spins``. Returns ``ν⁺``.
        """
        return self._inplane(nu, old, new, self.roller_rows(new, thetas)[0], spins)

    @functools.cached_property
    def _inplane_metric(self) -> np.ndarray:
        """``blockdiag(P, I_w 1, I_r 1)`` of :meth:`inplane_impact` (read-only)."""
        Mw = np.zeros((9, 9))
        Mw[:3, :3] = np.diag([self.mass, self.mass, self.inertia[2, 2]])
        Mw[3:6, 3:6] = self.wheel_inertia * np.eye(3)
        Mw[6:, 6:] = self.roller_axial * np.eye(3)
        Mw.setflags(write=False)
        return Mw

    def _inplane(self, nu: np.ndarray, old: tuple[int, ...], new: tuple[int, ...],
                 ks: np.ndarray, spins: np.ndarray) -> np.ndarray:
        """:meth:`inplane_impact` with the new mode's rows ``k_i`` given."""
        H_old, H_new = self.jacobian(old), self.jacobian(new)
        Mw = self._inplane_metric
        w = np.concatenate([nu, H_old @ nu, spins])
        A = np.hstack([np.vstack([H_new, ks]), -np.eye(6)])
        if self.roller_axial == 0.0:  # massless rollers: no spin to project
            Mw, w, A = Mw[:6, :6], w[:6], A[:3, :6]
        Minv_At = np.linalg.solve(Mw, A.T)
        lam = np.linalg.solve(A @ Minv_At, A @ w)
        return (w - Minv_At @ lam)[:3]

    def vertical_impulses(self, nu: np.ndarray, old: tuple[int, ...], new: tuple[int, ...],
                          thetas: np.ndarray, spins: np.ndarray) -> np.ndarray:
        """Generalised impulses ``x_c Λ_z,i`` on the wheel spins of the full impact.

        ``Λ`` from :meth:`impact` on the lifted velocity; the z-row of wheel i has
        ``−x_c`` in its θ̇ column, so ``q̇⁺ = q̇⁻ − 𝕄⁻¹AᵀΛ`` gives θ_i the impulse
        ``x_c Λ_z,i``.
        """
        q = self.lift(nu, old, thetas, roller_rates=spins)
        A = self.constraint_rows(new, thetas)
        cols, rows = self._massive(A)
        Ar = A[np.ix_(rows, cols)]
        impulse = np.linalg.solve(Ar @ self._full_mass_inv(cols.size) @ Ar.T, Ar @ q[cols])
        xc = -A[[1, 4, 7], [6, 7, 8]]  # the z-rows' θ̇ entries: −x_c(φ_i)
        step = 3 if cols.size == 12 else 2
        return xc * impulse[1::step]

    def remove_energy(self, nu: np.ndarray, modes: tuple[int, ...], thetas: np.ndarray,
                      wheel: int, energy: float, m_red: np.ndarray | None = None
                      ) -> np.ndarray:
        """Take ``energy`` out of wheel ``wheel``'s rolling by an impulse J along ``H_i``.

        ``T(ν − M⁻¹H_iᵀJ) = T − s J + ½ c J²`` with ``s = H_i ν``, ``c = H_i M⁻¹ H_iᵀ``;
        J is the root of ``½ c J² − s J + ΔE = 0`` nearer zero (``s/c``, the wheel's
        share brought to rest, if ΔE exceeds it).
        """
        h = self.jacobian(modes)[wheel]
        if m_red is None:  # the planar mass matrix of mode σ (given: already known)
            m_red = self.planar_mass(modes, thetas)
        rate = float(h @ nu)
        c = float(h @ np.linalg.solve(m_red, h))
        disc = rate * rate - 2.0 * c * energy
        j = (rate - math.copysign(math.sqrt(disc), rate)) / c if disc > 0 else rate / c
        return nu - np.linalg.solve(m_red, h * j)

    def overlap_impulse(self, nu: np.ndarray, modes: tuple[int, ...], thetas: np.ndarray,
                        wheel: int, rate: float, accel: float = 0.0) -> float:
        """Yaw angular impulse of the two rows' friction while both touch, N·m·s.

        Compliant contacts overlap over ``Δφ_w = δ / |x_c|`` of wheel rotation (the two
        rollers' heights differ by ``2 |x_c| |φ − φ_s|`` and both touch while that is
        under δ), i.e. for ``Δt_w = Δφ_w / |θ̇|``. Their levers ``L ± e`` ask rim speeds
        ``2 e r`` apart; each contact slides at ``e |r|``. The pair carries the Coulomb
        force ``μ min(N_old, N_new)``, on average ``μ N / 4`` with the load moving
        linearly across the window, unless the soft contact's tangential damping
        ``(N/g)(2/t_c) e |r|`` is smaller (slow turning): force ``f``, at levers
        ``L ± e``: a yaw moment ``2 e f`` against r and no net force. Impulse
        ``2 e f Δt_w``, ``Δt_w`` the time the wheel takes to cross the window
        (:func:`crossing_time`) at its rate ``θ̇`` and acceleration ``θ̈`` (``accel``, the
        continuous phase's at the hand-over): ``Δφ_w / |θ̇|`` while the wheel turns fast,
        bounded by ``√(2 Δφ_w / |θ̈|)`` where it turns back inside the window (a wheel
        whose rate passes through zero at the hand-over: ``Δφ_w/|θ̇|`` alone diverges there
        and would stop the platform's yaw).
        """
        if self.penetration == 0.0 or (rate == 0.0 and accel == 0.0):
            return 0.0
        g = self.rollers
        phi = float(g.phases(float(thetas[wheel]))[modes[wheel]])
        window = self.penetration / max(abs(float(g.contact_ahead(phi))), 1e-12)
        e = abs(float(g.offsets[modes[wheel]]))
        load = self.mass * self.gravity / 3.0
        force = self.friction * load / 4.0
        if self.contact_timeconst > 0.0:
            force = min(force, load / self.gravity * 2.0 / self.contact_timeconst
                        * e * abs(float(nu[2])))
        return 2.0 * e * force * crossing_time(window, rate, accel)

    @property
    def handover_dissipation(self) -> float:
        """``½ N δ`` with ``N = M g / 3``: the loaded contact's stored energy, J."""
        return 0.5 * self.mass * self.gravity / 3.0 * self.penetration

    def planar_impact(self, nu: np.ndarray, old: tuple[int, ...], new: tuple[int, ...],
                      thetas: np.ndarray, spins: np.ndarray,
                      wheel_accels: np.ndarray | None = None) -> tuple[np.ndarray, float]:
        """Switch from mode ``old`` to ``new`` in the planar model: ``(ν⁺, ΔT)``.

        1. :meth:`inplane_impact` (row lever L ± e, entering roller spins);
        2. the vertical impulses of the full rigid impact on the wheel spins
           (:meth:`vertical_impulses`): ``Δν = M_red⁻¹ H_newᵀ (x_c Λ_z)``;
        3. compliant contacts: :attr:`handover_dissipation` per switching wheel
           (:meth:`remove_energy`) and the rows' friction while both touch
           (:meth:`overlap_impulse`, with the wheels' accelerations ``wheel_accels`` θ̈
           of the continuous phase at the hand-over; None: zero).
        """
        accels = np.zeros(3) if wheel_accels is None else np.asarray(wheel_accels, float)
        ks, _ = self.roller_rows(new, thetas)  # the new mode's rows, shared by the steps
        nu_plus = self._inplane(nu, old, new, ks, spins)
        J = self.vertical_impulses(nu, old, new, thetas, spins)
        H_new = self.jacobian(new)
        m_red = self.planar_mass(new, thetas, ks)
        nu_plus = nu_plus + np.linalg.solve(m_red, H_new.T @ J)
        if self.penetration > 0:
            for i in range(3):
                if new[i] != old[i]:
                    nu_plus = self.remove_energy(nu_plus, new, thetas, i,
                                                 self.handover_dissipation, m_red)
                    rate = float(H_new[i] @ nu_plus)
                    impulse = self.overlap_impulse(nu_plus, new, thetas, i, rate,
                                                   float(accels[i]))
                    dnu = np.linalg.solve(m_red, np.array([0.0, 0.0, impulse]))
                    if abs(dnu[2]) >= abs(nu_plus[2]):  # friction stops, never reverses
                        dnu *= abs(nu_plus[2]) / max(abs(dnu[2]), 1e-300)
                    nu_plus = nu_plus - math.copysign(1.0, nu_plus[2]) * dnu
        lost = (self.kinetic_energy(nu, old, thetas) + 0.5 * self.roller_axial * (
            spins @ spins - (ks @ nu) @ (ks @ nu)) - 0.5 * nu_plus @ m_red @ nu_plus)
        return nu_plus, float(lost)

    def full_energy(self, q: np.ndarray) -> float:
        """``½ q̇ᵀ 𝕄 q̇``."""
        return float(0.5 * q @ self.full_mass() @ q)
