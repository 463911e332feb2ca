"""Equations of motion of an omni-wheeled platform, in the body frame (lecture §6).

State: body twist ``ν = (u, v, r)`` (see :mod:`omni_kinematics`), wheel rates ``θ̇``.
Parameters: total mass M and yaw inertia I_z about the centre (platform, wheels and rollers
together), wheel spin inertia I_w about each axle, wheel Jacobian ``H`` (``θ̇ = H ν``; the
lecture's ``(1/r) J``). Rollers' own spin inertia is neglected.

Unreduced (Newton–Euler in the body frame, traction forces F_t along the drive directions)::

    diag(M, M, I_z) ν̇ + r [−M v, M u, 0]ᵀ = Hᵀ r_w F_t        (platform)
    I_w θ̈ + r_w F_t = τ                                        (wheels)
    θ̇ = H ν   ⇒   θ̈ = H ν̇   (H is constant in the body frame)

The ``r``-term is the rigid-body term of body-frame velocities (the lecture's ψ̇ matrix);
``r_w Hᵀ`` is the lecture's ``r Rᵀ`` with ``R = H`` (virtual power ``F_tᵀ r_w θ̇``).
Eliminating ``F_t = (τ − I_w H ν̇)/r_w`` gives the reduced equations::

    (diag(M, M, I_z) + I_w HᵀH) ν̇ + r [−M v, M u, 0]ᵀ = Hᵀ τ

Note that wheel inertia enters the mass matrix but **not** the ``r``-term: substituting
``θ̇ = H ν`` into the Lagrangian before differentiating (illegitimate, the constraint is
non-holonomic in world coordinates) would put ``M + I_w (HᵀH)₁₁`` there instead. The
multiplier form :func:`multiplier_solution` (Lagrange–d'Alembert in the velocities
``(ν, θ̇)``) checks the reduction.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.analytic.checks import as_array, positive
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok


@dataclass(frozen=True)
class OmniDynamics:
    """Inertial parameters and wheel layout of an omni platform.

    Attributes:
        mass: total mass M, kg.
        yaw_inertia: total inertia I_z about the vertical through the centre, kg·m².
        wheel_inertia: spin inertia I_w of each wheel (with its rollers), kg·m².
        layout: wheel geometry (all radii equal).
    """

    mass: float
    yaw_inertia: float
    wheel_inertia: float
    layout: ok.WheelLayout

    def __post_init__(self) -> None:
        positive("mass", self.mass)
        positive("yaw_inertia", self.yaw_inertia)
        positive("wheel_inertia", self.wheel_inertia)
        if not isinstance(self.layout, ok.WheelLayout):
            raise ValueError(f"layout must be a WheelLayout, got {type(self.layout).__name__}")

    @functools.cached_property
    def H(self) -> np.ndarray:
        """Wheel Jacobian, ``θ̇ = H ν`` (computed once)."""
        return ok.wheel_jacobian(self.layout)

    @property
    def platform_matrix(self) -> np.ndarray:
        """``diag(M, M, I_z)``."""
        return np.diag([self.mass, self.mass, self.yaw_inertia])

    @functools.cached_property
    def mass_matrix(self) -> np.ndarray:
        """Reduced mass matrix ``diag(M, M, I_z) + I_w HᵀH`` (computed once, read-only)."""
        m = self.platform_matrix + self.wheel_inertia * self.H.T @ self.H
        m.setflags(write=False)
        return m

    def velocity_term(self, nu: np.ndarray) -> np.ndarray:
        """``r [−M v, M u, 0]``: the body-frame rigid-body term."""
        u, v, r = as_array("nu", nu, (3,))
        return np.array([-self.mass * r * v, self.mass * r * u, 0.0])

    def body_acceleration(self, nu: np.ndarray, torques: np.ndarray) -> np.ndarray:
        """``ν̇`` from the reduced equations."""
        tau = as_array("torques", torques, (self.layout.n,))
        return np.linalg.solve(self.mass_matrix, self.H.T @ tau - self.velocity_term(nu))

    def traction_forces(self, nu: np.ndarray, torques: np.ndarray) -> np.ndarray:
        """Traction forces ``F_t = (τ − I_w H ν̇)/r_w`` along the drive directions, N."""
        tau = as_array("torques", torques, (self.layout.n,))
        nudot = self.body_acceleration(nu, tau)
        return (tau - self.wheel_inertia * self.H @ nudot) / self.layout.radii

    def multiplier_solution(self, nu: np.ndarray, torques: np.ndarray
                            ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Solve the unreduced system with multipliers for ``(ν̇, θ̈, λ)``.

        Velocities ``w = (ν, θ̇)``, mass ``blockdiag(diag(M, M, I_z), I_w 1)``, constraint
        ``A w = 0`` with ``A = [H, −1]``::

            [[M_w, Aᵀ], [A, 0]] [ẇ; −λ] = [Q − c; 0],   Q = (0, τ),   c = (r-term, 0)

        ``λ_i`` is the constraint force on wheel i's rolling; physically ``λ = r_w F_t``.
        """
        nu = as_array("nu", nu, (3,))
        tau = as_array("torques", torques, (self.layout.n,))
        n = self.layout.n
        Mw = np.zeros((3 + n, 3 + n))
        Mw[:3, :3] = self.platform_matrix
        Mw[3:, 3:] = self.wheel_inertia * np.eye(n)
        A = np.hstack([self.H, -np.eye(n)])
        kkt = np.block([[Mw, A.T], [A, np.zeros((n, n))]])
        rhs = np.concatenate([-self.velocity_term(nu), tau, np.zeros(n)])
        sol = np.linalg.solve(kkt, rhs)
        return sol[:3], sol[3:3 + n], -sol[3 + n:]

    def kinetic_energy(self, nu: np.ndarray) -> float:
        """``T = ½ νᵀ diag(M, M, I_z) ν + ½ I_w |H ν|²``."""
        nu = as_array("nu", nu, (3,))
        return float(0.5 * nu @ self.platform_matrix @ nu
                     + 0.5 * self.wheel_inertia * np.sum((self.H @ nu) ** 2))

    def state_derivative(self, state: np.ndarray, torques: np.ndarray) -> np.ndarray:
        """``d/dt (X, Y, ψ, u, v, r)`` with world pose and body twist."""
        state = as_array("state", state, (6,))
        nu = state[3:]
        return np.concatenate([ok.body_to_world(state[2], nu),
                               self.body_acceleration(nu, torques)])


def rk4_trajectory(dyn: OmniDynamics, x0: np.ndarray, torques: np.ndarray, dt: float
                   ) -> np.ndarray:
    """States of ``rk4_step(state_derivative)`` step after step, the same floats, faster.

    :func:`wmr_mujoco.analytic.integrate.rk4_step` on :meth:`OmniDynamics.state_derivative`
    with the torques ``torques[k]`` held over step k: the elementwise arithmetic on Python
    floats in numpy's order of evaluation (``x + (Δt/2) k₁``, ``x + (Δt/6)(((k₁ + 2k₂) +
    2k₃) + k₄)``, ``r [−M v, M u, 0]``), the products ``Hᵀ τ`` (once per distinct τ) and the
    solves with the mass matrix the very numpy calls of
    :meth:`OmniDynamics.body_acceleration`. A state or a torque that is not finite raises
    where ``state_derivative`` would.

    Returns:
        (N + 1, 6) states, ``x0`` first.

    Raises:
        ValueError: non-finite torques, or a non-finite state (the run diverged).
    """
    n = dyn.layout.n
    ht, mm, m = dyn.H.T, dyn.mass_matrix, dyn.mass
    solve = np.linalg.solve
    inputs = np.asarray(torques, float)
    out = np.empty((len(inputs) + 1, 6))
    out[0] = as_array("state", x0, (6,))
    x = out[0].tolist()
    half, sixth = 0.5 * dt, dt / 6.0
    forcing: dict[bytes, tuple[float, float, float]] = {}

    def deriv(s: list[float], f: tuple[float, float, float]) -> list[float]:
        if not all(map(math.isfinite, s)):
            as_array("state", np.array(s), (6,))  # raises, as state_derivative
        u, v, r = s[3], s[4], s[5]
        c, sn = math.cos(s[2]), math.sin(s[2])
        acc = solve(mm, np.array([f[0] - -m * r * v, f[1] - m * r * u, f[2] - 0.0]))
        return [c * u - sn * v, sn * u + c * v, r, *acc.tolist()]

    for k, tau in enumerate(inputs):
        f = forcing.get(key := tau.tobytes())
        if f is None:
            f = forcing[key] = tuple((ht @ as_array("torques", tau, (n,))).tolist())
        k1 = deriv(x, f)
        k2 = deriv([a + half * b for a, b in zip(x, k1, strict=True)], f)
        k3 = deriv([a + half * b for a, b in zip(x, k2, strict=True)], f)
        k4 = deriv([a + dt * b for a, b in zip(x, k3, strict=True)], f)
        x = [a + sixth * (((b + 2.0 * c) + 2.0 * d) + e)
             for a, b, c, d, e in zip(x, k1, k2, k3, k4, strict=True)]
        out[k + 1] = x
    return out
