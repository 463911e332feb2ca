"""Go to a pose in polar coordinates (Astolfi's law).

Sources: Astolfi 1999; Siegwart, Nourbakhsh & Scaramuzza, "Introduction to Autonomous
Mobile Robots", 2nd ed., §3.6.2.4.

In the goal's frame (goal at the origin, heading 0) the robot at ``(Δx, Δy, θ)`` is
described by

    ρ = √(Δx² + Δy²),   α = −θ + atan2(−Δy, −Δx),   β = −θ − α,

(distance to the goal, bearing of the goal from the heading, and the goal heading seen
from the line of sight). The law

    v = k_ρ ρ,   ω = k_α α + k_β β

gives the closed loop ``ρ̇ = −k_ρ ρ cos α``, ``α̇ = k_ρ sin α − k_α α − k_β β``,
``β̇ = −k_ρ sin α``; linearised at the goal

    ρ̇ = −k_ρ ρ,   [α̇, β̇]ᵀ = [[−(k_α − k_ρ), −k_β], [−k_ρ, 0]] [α, β]ᵀ,

characteristic polynomial ``s² + (k_α − k_ρ) s − k_ρ k_β``: exponentially stable iff

    k_ρ > 0,   k_β < 0,   k_α − k_ρ > 0.

The default gains ``(k_ρ, k_α, k_β) = (1, 6, −5)`` put both angular roots
(``−1.38``, ``−3.62`` 1/s) below ``−k_ρ``: the angles settle before the distance does, so
the heading has converged by the time ``ρ`` reaches round-off (with Siegwart's example
``(3, 8, −1.5)`` the distance decays faster than the angles, and once ``ρ`` is at machine
precision the polar angles are undefined and the last heading error is never removed).
Both roots lie below ``−k_ρ`` iff ``k_α > 3 k_ρ`` and ``−k_β > k_α − 2 k_ρ``.

When the goal lies behind (``α ∉ (−π/2, π/2]``) the robot backs up: ``v = −k_ρ ρ`` with
``α = −θ + atan2(Δy, Δx)`` measured from the reversed heading (Siegwart's remark), so the
same analysis holds.
Speed and yaw-rate saturation keep the direction of the command (both scaled together).

The polar coordinates are singular at the goal: at ``ρ → 0`` the angles ``α, β`` are
undefined, and in the physics micrometres of contact jitter swing them by radians (the
law then spins the robot away again). Within ``tolerance`` of the goal position the
command is zero: the robot has arrived (the gains above bring the heading in first, so
it has arrived in heading too — ``|β| < |ρ|``-order).
"""

from __future__ import annotations

import math

import numpy as np

from wmr_mujoco.loop.control.base import CommandKind, Controller, StateLike, positive, wrap


class GoToPose(Controller):
    """Astolfi's polar go-to-pose law (module docstring); writes ``(v, ω)``.

    Args:
        k_rho, k_alpha, k_beta: gains, 1/s (module docstring).
        max_speed: |v| limit, m/s.
        max_rate: |ω| limit, rad/s.
        reverse: allow backing up to a goal behind.
        tolerance: arrival distance, m (0: never stop).

    Raises:
        ValueError: gains violating the stability conditions, or bad limits.
    """

    name = "go_to_pose"
    kinds = (CommandKind.UNICYCLE,)
    reference_type = "pose"

    def __init__(self, k_rho: float = 1.0, k_alpha: float = 6.0, k_beta: float = -5.0,
                 max_speed: float = 0.5, max_rate: float = 2.0, reverse: bool = True,
                 tolerance: float = 1e-3,
                 kind: CommandKind | str = CommandKind.UNICYCLE) -> None:
        gains = (k_rho, k_alpha, k_beta)
        if not all(isinstance(g, (int, float)) and math.isfinite(g) for g in gains) or not (
                k_rho > 0 and k_beta < 0 and k_alpha - k_rho > 0):
            raise ValueError(f"gains (k_rho, k_alpha, k_beta) = {gains!r}; Astolfi's stability "
                             "conditions need k_rho > 0, k_beta < 0, k_alpha - k_rho > 0")
        self.k_rho, self.k_alpha, self.k_beta = float(k_rho), float(k_alpha), float(k_beta)
        self.max_speed = positive("max_speed", max_speed)
        self.max_rate = positive("max_rate", max_rate)
        self.reverse = bool(reverse)
        if not (isinstance(tolerance, (int, float)) and math.isfinite(tolerance)
                and tolerance >= 0):
            raise ValueError(f"tolerance = {tolerance!r}; must be a finite number >= 0 m")
        self.tolerance = float(tolerance)
        super().__init__(kind)

    def linear_matrix(self) -> np.ndarray:
        """The closed loop linearised at the goal, on ``(ρ, α, β)``, 1/s."""
        kr, ka, kb = self.k_rho, self.k_alpha, self.k_beta
        return np.array([[-kr, 0.0, 0.0], [0.0, -(ka - kr), -kb], [0.0, -kr, 0.0]])

    def polar(self, pose: np.ndarray, goal: np.ndarray) -> tuple[float, float, float, float]:
        """``(ρ, α, β, direction)`` of ``pose`` relative to ``goal`` (direction ±1)."""
        cg, sg = math.cos(goal[2]), math.sin(goal[2])
        dx, dy = pose[0] - goal[0], pose[1] - goal[1]
        x, y = cg * dx + sg * dy, -sg * dx + cg * dy  # robot in the goal frame
        theta = wrap(pose[2] - goal[2])
        rho = math.hypot(x, y)
        alpha = wrap(-theta + math.atan2(-y, -x))
        direction = 1.0
        if self.reverse and abs(alpha) > math.pi / 2:
            # The robot backing up is a robot of heading θ + π driving forward to a goal
            # of heading π: in that goal's frame (x, y) → (−x, −y) and θ stays θ.
            direction = -1.0
            alpha = wrap(-theta + math.atan2(y, x))
        beta = wrap(-theta - alpha)
        return rho, alpha, beta, direction

    def __call__(self, state: StateLike, reference: np.ndarray, t: float) -> np.ndarray:
        """``(v, ω)`` toward the goal pose ``reference = (x, y, ψ)``."""
        goal = np.asarray(reference, float)
        if goal.shape != (3,) or not np.isfinite(goal).all():
            raise ValueError(f"goal pose = {reference!r}; must be a finite (x, y, heading)")
        rho, alpha, beta, direction = self.polar(np.asarray(state.pose, float), goal)
        if rho < self.tolerance:
            return np.zeros(2)
        v = direction * self.k_rho * rho
        omega = self.k_alpha * alpha + self.k_beta * beta
        scale = max(1.0, abs(v) / self.max_speed, abs(omega) / self.max_rate)
        return np.array([v / scale, omega / scale])
