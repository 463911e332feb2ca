"""Stanley path following.

Source: Thrun et al. 2006, "Stanley: The Robot that Won the DARPA Grand Challenge",
J. Field Robotics 23(9), §9.2.

The front axle (distance ℓ ahead of the reference point) has cross-track error ``e``
(> 0: left of the path) and the vehicle's heading differs from the path's at the
nearest point by ``ψ_e = ψ_path − ψ``. The steering angle

    δ = ψ_e − atan(k e / (k_s + v)),    clipped to ``[−δ_max, δ_max]``,

with speed ``v`` and softening ``k_s`` (Thrun's, for low speed). The front axle moves
along ``ψ + δ`` with speed ``v_f = v / cos δ``, so on a straight path (unsaturated)

    ė = v_f sin(ψ + δ − ψ_path) = −v_f sin(atan(k e / (k_s + v))),

independently of the heading: for small ``e`` and ``δ`` (``v_f ≈ v``) the error decays
as ``e(t) = e₀ exp(−k v t / (k_s + v))`` (rate ``k`` when ``k_s = 0``), the paper's
exponential convergence. A unicycle follows it through a virtual wheelbase:
``ω = v tan δ / ℓ`` turns it exactly as the car (``base.steer_command``).
"""

from __future__ import annotations

import math

import numpy as np

from wmr_mujoco.loop.control.base import (
    CommandKind,
    Controller,
    StateLike,
    clip,
    command_kind,
    positive,
    steer_command,
    wrap,
)
from wmr_mujoco.loop.control.paths import Path


class Stanley(Controller):
    """Thrun et al.'s Stanley steering law (module docstring) at constant speed.

    Args:
        speed: ``v``, m/s.
        gain: ``k``, 1/s.
        wheelbase: ℓ (the front axle's distance ahead of the pose), m.
        softening: ``k_s``, m/s.
        max_steer: ``δ_max``, rad.
        kind: ``"car"`` or ``"unicycle"`` (virtual wheelbase).
    """

    name = "stanley"
    kinds = (CommandKind.CAR, CommandKind.UNICYCLE)
    reference_type = "path"

    def __init__(self, speed: float = 0.5, gain: float = 1.0, wheelbase: float = 0.3,
                 softening: float = 0.0, max_steer: float = 1.0,
                 kind: CommandKind | str = CommandKind.CAR) -> None:
        self.speed = positive("speed", speed)
        self.gain = positive("gain", gain)
        self.wheelbase = positive("wheelbase", wheelbase)
        if not (math.isfinite(softening) and softening >= 0):
            raise ValueError(f"softening = {softening!r}; must be a finite number >= 0 m/s")
        self.softening = float(softening)
        self.max_steer = positive("max_steer", max_steer)
        super().__init__(command_kind(kind))

    def reset(self) -> None:
        """Start the progress along the path at its start.

        The search for the nearest point then follows the path, even where it crosses
        itself (the figure eight).
        """
        self._s: float = 0.0

    def tracking_point(self, pose: np.ndarray) -> np.ndarray:
        """The front axle, which the law steers onto the path."""
        return self.front_axle(pose)

    def front_axle(self, pose: np.ndarray) -> np.ndarray:
        """``(x, y)`` of the front axle: ℓ ahead of the pose along its heading."""
        return np.array([pose[0] + self.wheelbase * math.cos(pose[2]),
                         pose[1] + self.wheelbase * math.sin(pose[2])])

    def steer(self, state: StateLike, path: Path) -> float:
        """``δ = ψ_e − atan(k e / (k_s + v))``, clipped."""
        pose = np.asarray(state.pose, float)
        front = self.front_axle(pose)
        point = path.closest(front, self._s)
        self._s = point.s
        rel = front - point.position
        e = -math.sin(point.heading) * rel[0] + math.cos(point.heading) * rel[1]
        delta = wrap(point.heading - pose[2]) - math.atan2(self.gain * e,
                                                           self.softening + self.speed)
        return clip(delta, -self.max_steer, self.max_steer)

    def __call__(self, state: StateLike, reference: Path, t: float) -> np.ndarray:
        """``(v, δ)`` or ``(v, ω)`` following the path ``reference``."""
        return steer_command(self.kind, self.speed, self.steer(state, reference),
                             self.wheelbase)
