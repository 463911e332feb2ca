"""A short manoeuvre per robot, simulated and summarised (``wmr demo``)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.adapters import base_pose
from wmr_mujoco.loading import load
from wmr_mujoco.simulation import rollout


@dataclass(frozen=True)
class Manoeuvre:
    """Piecewise-constant inputs: ``(duration s, wheel ground speed m/s, steering rate rad/s)``.

    The wheel speed is the driven wheel's ``v = R θ̇``; the control sent to the wheel
    servo is ``θ̇ = v / R``.
    """

    robot: str
    description: str
    wheel_radius: float
    segments: tuple[tuple[float, float, float], ...]

    @property
    def duration(self) -> float:
        """Total duration, s."""
        return sum(s[0] for s in self.segments)

    def control(self, t: float) -> np.ndarray:
        """Actuator controls ``[θ̇, ω]`` at time ``t``."""
        end = 0.0
        for duration, speed, steer_rate in self.segments:
            end += duration
            if t < end:
                return np.array([speed / self.wheel_radius, steer_rate])
        return np.zeros(2)


MANOEUVRES = (
    Manoeuvre("disc", "roll 1 m/s, steer 0.5 rad/s for 2 s, roll on", 0.15,
              ((1.0, 1.0, 0.0), (2.0, 1.0, 0.5), (1.0, 1.0, 0.0))),
    Manoeuvre("bicycle", "rear wheel 2 m/s, steer to 0.3 rad, hold, steer back", 0.34,
              ((1.0, 2.0, 0.0), (0.5, 2.0, 0.6), (2.0, 2.0, 0.0), (0.5, 2.0, -0.6))),
    Manoeuvre("tricycle", "left rear wheel 1 m/s, steer to 0.4 rad and hold", 0.1,
              ((1.0, 1.0, 0.0), (0.4, 1.0, 1.0), (2.6, 1.0, 0.0))),
)


def run_demo() -> str:
    """Simulate every manoeuvre and return a text summary."""
    lines = [f"{'robot':<9} {'manoeuvre':<55} {'path m':>7} {'end x, y (m)':>16} "
             f"{'heading':>8}"]
    for man in MANOEUVRES:
        model = load(man.robot)
        data = mujoco.MjData(model)
        mujoco.mj_forward(model, data)
        traj = rollout(model, data, man.duration, man.control, record_every=10,
                       recorder=base_pose)
        path = float(np.sum(np.hypot(*np.diff(traj[:, :2], axis=0).T)))
        x, y, heading = traj[-1]
        lines.append(f"{man.robot:<9} {man.description:<55} {path:7.3f} "
                     f"{x:7.3f}, {y:7.3f} {math.degrees(heading):7.1f}°")
    return "\n".join(lines)
