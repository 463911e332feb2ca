"""Validation scenarios, as data: robot, inputs as signals, duration, targets.

Every scenario runs the same inputs through MuJoCo and through the analytic model
(:mod:`wmr_mujoco.validation`). Inputs are in the lecture's terms (see
:mod:`wmr_mujoco.adapters`); speeds ramp up from rest so that traction stays below μN.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from wmr_mujoco.signals import Piecewise, Signal, Sine, const, pulses

#: Targets (issue #5): final position error in % of path, lateral slip RMS in m/s, omni
#: body-velocity error after 2 s of torques in %, single-wheel acceleration error in %.
POSITION_PCT = {"disc": 0.5, "bicycle": 0.5, "tricycle": 0.5, "omni3": 1.0}
HEADING_DEG_OMNI = 1.0
LATERAL_SLIP_RMS = 1e-3
ROLLER_RATE_PCT = 5.0
OMNI_VELOCITY_PCT = 3.0
WHEEL_ACCEL_PCT = 1.0

#: Omni open-loop manoeuvres, shared with :mod:`wmr_mujoco.omni_trials`: translation
#: directions (degrees in the body frame), speed (m/s) and yaw rate (rad/s).
OMNI_DIRECTIONS_DEG = tuple(range(0, 360, 45))
OMNI_SPEED = 0.3
OMNI_YAW_RATE = 1.0


@dataclass(frozen=True)
class Scenario:
    """One validation run.

    Attributes:
        robot: registry name.
        name: short label, unique per robot.
        inputs: one signal per input channel (see :mod:`wmr_mujoco.adapters`).
        duration: seconds after the settle.
        kind: ``"kinematic"`` (rate inputs) or ``"dynamic"`` (torque inputs).
        world_frame: omni only: inputs are world rates (Ẋ, Ẏ, ψ̇).
        settle: seconds at rest before the inputs start.
    """

    robot: str
    name: str
    inputs: tuple[Signal, ...]
    duration: float = 10.0
    kind: str = "kinematic"
    world_frame: bool = False
    settle: float = 0.5
    description: str = field(default="", compare=False)

    @property
    def key(self) -> str:
        """``robot/name``."""
        return f"{self.robot}/{self.name}"

    def input_at(self, t: float) -> np.ndarray:
        """Input vector at time ``t`` after the settle."""
        return np.array([s(t) for s in self.inputs])


def _steer_to(angle: float, start: float = 0.0, time: float = 0.5) -> Piecewise:
    """Steering-rate pulse that turns the steering by ``angle`` over ``time`` seconds."""
    return pulses((start, start + time, angle / time))


def _square_with_rotation(side: float = 0.6, speed: float = 0.24, yaw_rate: float = 0.4
                          ) -> tuple[Signal, ...]:
    """World-frame square (four legs) while the platform spins at a constant rate."""
    leg = side / speed
    ramp = 0.3
    xs, ys = [(0.0, 0.0)], [(0.0, 0.0)]
    for k in range(4):
        t0 = 0.5 + k * leg
        vx, vy = speed * math.cos(k * math.pi / 2), speed * math.sin(k * math.pi / 2)
        for knots, v in ((xs, vx), (ys, vy)):
            knots += [(t0, 0.0), (t0 + ramp, v), (t0 + leg - ramp, v), (t0 + leg, 0.0)]
    return (Piecewise(tuple(xs)), Piecewise(tuple(ys)), const(yaw_rate, 0.5))


def _omni_translation(deg: int, speed: float = OMNI_SPEED) -> tuple[Signal, ...]:
    a = math.radians(deg)
    return (const(speed * math.cos(a), 0.5), const(speed * math.sin(a), 0.5), const(0.0))


SCENARIOS: tuple[Scenario, ...] = (
    # Disc: inputs (v, ω).
    Scenario("disc", "straight", (const(1.0, 0.5), const(0.0))),
    Scenario("disc", "constant steering", (const(1.0, 0.5), const(0.5))),
    Scenario("disc", "sinusoidal steering", (const(1.0, 0.5), Sine(0.8, 4.0))),
    Scenario("disc", "torque", (const(0.3), const(0.0)), duration=2.0, kind="dynamic"),
    # Bicycle: inputs (v_r, ω).
    *(Scenario("bicycle", f"steady turn {phi:g} rad", (const(2.0, 1.0), _steer_to(phi)))
      for phi in (0.15, 0.3, 0.5)),
    Scenario("bicycle", "steering ramp", (const(2.0, 1.0), const(0.05))),
    Scenario("bicycle", "lane change", (const(2.0, 1.0), pulses(
        (2.0, 2.5, 0.4), (2.5, 3.5, -0.4), (3.5, 4.0, 0.4)))),
    # Tricycle: inputs (v_L, ω).
    # The driven wheel is the inner one in left turns: speed first, then steering, so
    # that the midpoint's acceleration v_L/(1 − k) stays below the traction limit.
    *(Scenario("tricycle", f"steady turn {phi:g} rad", (const(1.0, 1.0), _steer_to(phi, 1.0)))
      for phi in (0.2, 0.4, 0.6)),
    # Steer to +0.5 rad, one full circle (about 4.5 s), steer through to −0.5, a second.
    Scenario("tricycle", "figure eight", (const(1.0, 1.0), pulses(
        (1.0, 1.5, 1.0), (5.7, 6.7, -1.0))), duration=12.0),
    # Omni: inputs (u, v, r) in the body frame, or world rates.
    *(Scenario("omni3", f"translate {deg}°", _omni_translation(deg))
      for deg in OMNI_DIRECTIONS_DEG),
    Scenario("omni3", "rotate", (const(0.0), const(0.0), const(OMNI_YAW_RATE, 0.5))),
    Scenario("omni3", "translate+rotate", (const(OMNI_SPEED, 0.5), const(0.0),
                                           const(0.5 * OMNI_YAW_RATE, 0.5))),
    Scenario("omni3", "square with rotation", _square_with_rotation(), world_frame=True),
    Scenario("omni3", "torque", (const(0.04), const(-0.03), const(0.01)), duration=2.0,
             kind="dynamic"),
)


def scenarios_for(robots: list[str] | tuple[str, ...] | None = None) -> list[Scenario]:
    """Scenarios of the given robots (all if None), in table order.

    Raises:
        ValueError: a robot without scenarios; the message lists those with some.
    """
    have = list(dict.fromkeys(s.robot for s in SCENARIOS))
    if robots is None:
        return list(SCENARIOS)
    for r in robots:
        if r not in have:
            raise ValueError(f"no validation scenarios for robot {r!r}; robots with "
                             f"scenarios: {', '.join(have)}")
    return [s for s in SCENARIOS if s.robot in robots]
