"""Pure pursuit path following.

Source: Coulter 1992, "Implementation of the Pure Pursuit Path Tracking Algorithm",
CMU-RI-TR-92-01.

The goal point ``g`` is the first point of the path ahead of the robot at distance ``L``
(the lookahead) from its reference point (rear-axle or axle midpoint). In the body frame
``g`` lies at bearing ``α``; the circular arc through the robot, tangent to its heading,
and through ``g`` has curvature

    κ = 2 sin α / L,

which the robot follows: ``ω = v κ`` (unicycle) or ``δ = atan(ℓ κ)`` (car, wheelbase ℓ).

Closed loop (kinematic, constant speed ``v``):

* on a straight line, for small cross-track error ``e`` and heading error ``θ``, the goal
  point's lateral offset is ``−e − L θ``, so ``ė = v θ``, ``θ̇ = v κ = −2v (e + L θ)/L²``:
  ``s² + (2v/L) s + 2v²/L² = 0``, ``s = (v/L)(−1 ± i)`` — decay rate ``v/L``, damping
  ratio ``1/√2``;
* on a circle of radius ``R``, a robot on a concentric circle of radius ``r`` in steady
  state must see the goal point (on the path, distance ``L``) on its own arc:
  ``L² = R² + r² − 2Rr cos φ`` and ``1/r = 2 (r − R cos φ)/L²`` give ``r² = R²``: the
  steady-state cross-track error is ZERO (any lookahead). The error pure pursuit is
  known for (cutting corners) is a transient and a physical effect (slip, steering lag),
  which the physics run measures.
"""

from __future__ import annotations

import math

import numpy as np

from wmr_mujoco.loop.control.base import (
    CommandKind,
    Controller,
    StateLike,
    clip,
    positive,
    steer_command,
)
from wmr_mujoco.loop.control.paths import Path


class PurePursuit(Controller):
    """Coulter's pure pursuit (module docstring) at constant speed.

    Args:
        speed: forward speed, m/s.
        lookahead: ``L``, m.
        wheelbase: ℓ for car commands, m (None: unicycle commands ``(v, v κ)``).
        max_steer: steering-angle limit of a car, rad.
    """

    name = "pure_pursuit"
    kinds = (CommandKind.UNICYCLE, CommandKind.CAR)
    reference_type = "path"

    def __init__(self, speed: float = 0.5, lookahead: float = 0.6,
                 wheelbase: float | None = None, max_steer: float = 1.0) -> None:
        self.speed = positive("speed", speed)
        self.lookahead = positive("lookahead", lookahead)
        self.wheelbase = None if wheelbase is None else positive("wheelbase", wheelbase)
        self.max_steer = positive("max_steer", max_steer)
        super().__init__(CommandKind.UNICYCLE if wheelbase is None else CommandKind.CAR)

    def reset(self) -> None:
        """Start the progress along the path at its start.

        The search for the nearest point then follows the path, even where it crosses
        itself (the figure eight).
        """
        self._s: float = 0.0

    def curvature(self, state: StateLike, path: Path) -> float:
        """``κ = 2 sin α / L_d`` toward the goal point (``L_d`` its actual distance)."""
        x, y, psi = np.asarray(state.pose, float)[:3].tolist()
        self._s = path.closest((x, y), self._s).s
        goal = path.lookahead((x, y), self.lookahead, self._s).position
        dx, dy = goal[0] - x, goal[1] - y
        dist = math.hypot(dx, dy)
        if dist < 1e-9:
            return 0.0
        alpha = math.atan2(-math.sin(psi) * dx + math.cos(psi) * dy,
                           math.cos(psi) * dx + math.sin(psi) * dy)
        return 2.0 * math.sin(alpha) / dist

    def __call__(self, state: StateLike, reference: Path, t: float) -> np.ndarray:
        """``(v, ω)`` or ``(v, δ)`` following the path ``reference``."""
        kappa = self.curvature(state, reference)
        if self.wheelbase is None:
            return np.array([self.speed, self.speed * kappa])
        steer = clip(math.atan(self.wheelbase * kappa), -self.max_steer, self.max_steer)
        return steer_command(self.kind, self.speed, steer, self.wheelbase)
