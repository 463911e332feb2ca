"""Trajectory tracking for a unicycle (Kanayama's law).

Source: Kanayama, Kimura, Miyazaki & Noguchi 1990, "A Stable Tracking Control Method for
an Autonomous Mobile Robot", ICRA.

The reference ``(x_r, y_r, θ_r)`` moves with ``(v_r, ω_r)``. The error in the robot's
frame,

    [e_x, e_y]ᵀ = R(θ)ᵀ [x_r − x, y_r − y]ᵀ,   e_θ = θ_r − θ,

is driven to zero by

    v = v_r cos e_θ + K_x e_x,
    ω = ω_r + v_r (K_y e_y + K_θ sin e_θ),

stable (Lyapunov, the paper's Proposition) for ``K_x, K_y, K_θ > 0`` and ``v_r > 0``.
Linearised at zero error the error obeys

    ė = [[−K_x, ω_r, 0], [−ω_r, 0, v_r], [0, −v_r K_y, −v_r K_θ]] e,

on a straight reference (``ω_r = 0``) ``e_x`` decays at ``K_x`` and ``(e_y, e_θ)`` with
``s² + v_r K_θ s + v_r² K_y = 0``; the paper's critical damping ``K_θ = 2 √K_y`` gives a
double root ``s = −v_r √K_y``. A car follows through ``δ = atan(ℓ ω / v)``.
"""

from __future__ import annotations

import math

import numpy as np

from wmr_mujoco.loop.control.base import (
    CommandKind,
    Controller,
    StateLike,
    Trajectory,
    clip,
    positive,
    wrap,
)


class Kanayama(Controller):
    """Kanayama et al.'s tracking law (module docstring).

    Args:
        k_x: ``K_x``, 1/s.
        k_y: ``K_y``, 1/m².
        k_theta: ``K_θ``, 1/m (None: critical damping ``2 √K_y``).
        wheelbase: ℓ for car commands, m (None: unicycle commands).
        max_steer: steering-angle limit of a car, rad.
    """

    name = "kanayama"
    kinds = (CommandKind.UNICYCLE, CommandKind.CAR)
    reference_type = "trajectory"

    def __init__(self, k_x: float = 2.0, k_y: float = 16.0, k_theta: float | None = None,
                 wheelbase: float | None = None, max_steer: float = 1.0) -> None:
        self.k_x = positive("k_x", k_x)
        self.k_y = positive("k_y", k_y)
        self.k_theta = 2.0 * math.sqrt(self.k_y) if k_theta is None else positive(
            "k_theta", k_theta)
        self.wheelbase = None if wheelbase is None else positive("wheelbase", wheelbase)
        self.max_steer = positive("max_steer", max_steer)
        super().__init__(CommandKind.UNICYCLE if wheelbase is None else CommandKind.CAR)

    def linear_matrix(self, v_r: float, omega_r: float) -> np.ndarray:
        """The error dynamics linearised at zero error, on ``(e_x, e_y, e_θ)``, 1/s."""
        return np.array([[-self.k_x, omega_r, 0.0], [-omega_r, 0.0, v_r],
                         [0.0, -v_r * self.k_y, -v_r * self.k_theta]])

    @staticmethod
    def errors(pose: np.ndarray, ref: np.ndarray) -> np.ndarray:
        """``(e_x, e_y, e_θ)`` of ``pose`` against the reference pose, robot frame."""
        c, s = math.cos(pose[2]), math.sin(pose[2])
        dx, dy = ref[0] - pose[0], ref[1] - pose[1]
        return np.array([c * dx + s * dy, -s * dx + c * dy, wrap(ref[2] - pose[2])])

    def __call__(self, state: StateLike, reference: Trajectory, t: float) -> np.ndarray:
        """``(v, ω)`` or ``(v, δ)`` tracking the trajectory ``reference`` at time ``t``."""
        point, v_r, omega_r = reference.at(t)
        ex, ey, eth = self.errors(np.asarray(state.pose, float), point.pose)
        v = v_r * math.cos(eth) + self.k_x * ex
        omega = omega_r + v_r * (self.k_y * ey + self.k_theta * math.sin(eth))
        if self.wheelbase is None:
            return np.array([v, omega])
        steer = math.atan(self.wheelbase * omega / v) if abs(v) > 1e-6 else 0.0
        return np.array([v, clip(steer, -self.max_steer, self.max_steer)])
