"""The tricycle: steered front wheel, left rear wheel driven, right rear wheel free.

Kinematic inputs ``(v_L, ω)``: driven left rear wheel's ground speed and steering rate;
state ``(x, y, ψ, φ)`` of the rear-axle midpoint. The driven wheel at ``v_L`` moves the
midpoint at ``v_L / (1 − k)``, ``k = (w/2ℓ) tan φ`` (:mod:`wmr_mujoco.robots.tricycle.analytic`).

Probe: the free right wheel must turn at the ICR rate
``θ̇_R = θ̇_L (1 + k) / (1 − k)`` given the measured driven-wheel rate and steering angle.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import ClassVar

import mujoco
import numpy as np

from wmr_mujoco.analytic import bicycle
from wmr_mujoco.analytic.integrate import rk4_states
from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.builders.wheel_pairs import wheel_floor_pairs
from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.robots import requirements as req
from wmr_mujoco.robots.learning import Learning
from wmr_mujoco.robots.spec import Picture, RobotSpec
from wmr_mujoco.robots.tricycle import analytic as tricycle
from wmr_mujoco.robots.tricycle import builder
from wmr_mujoco.robots.tricycle.params import TricycleParams
from wmr_mujoco.validation import variations as var
from wmr_mujoco.validation.adapters import POSE_UNITS, Adapter, base_pose
from wmr_mujoco.validation.command import RateCommand, Servo
from wmr_mujoco.validation.family import Family
from wmr_mujoco.validation.metrics import Metric, Sample, Target, rms
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.signals import const, pulses, steer_to

NAME = "tricycle"


@dataclass(frozen=True)
class TricycleKinematics:
    """Tricycle: ``x = (x, y, ψ, φ)`` of the rear-axle midpoint; controls ``(v_L/R, ω)``."""

    #: ``sim_state`` reads the pose and joint positions alone (the runner's frames only).
    frames_only: ClassVar[bool] = True

    params: TricycleParams
    mode: ActuationMode = ActuationMode.RATE
    state_names: tuple[str, ...] = ("x", "y", "heading", "steer")
    state_units: tuple[str, ...] = (*POSE_UNITS, "rad")
    wheel_joints: tuple[str, ...] = ("rear_left_wheel", "rear_right_wheel", "front_wheel")
    lateral_wheels: tuple[str, ...] = ("rear_left_wheel", "rear_right_wheel", "front_wheel")

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """``(θ̇_L, ω) = (v_L / R, ω)``."""
        return np.array([u[0] / self.params.rear_wheel.radius, u[1]])

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Tricycle kinematics with the midpoint speed ``v_L / (1 − k)``."""
        p = self.params
        v_mid = tricycle.midpoint_speed_from_left(u[0], x[3], p.track, p.wheelbase)
        return tricycle.rates(x, np.array([v_mid, u[1]]), p.wheelbase)

    def trajectory(self, x0: np.ndarray, inputs: np.ndarray, dt: float) -> np.ndarray:
        """RK4 on :meth:`rhs` over every step at once (the floats of step after step).

        :func:`wmr_mujoco.analytic.bicycle.rk4_trajectory` with the midpoint speed
        ``v_L / (1 − k)`` at each stage's steering angle
        (:func:`~wmr_mujoco.robots.tricycle.analytic.midpoint_speeds`), or the steps one by
        one where it declines (a stage that is not finite, or the ICR on the driven wheel:
        they raise there).
        """
        p = self.params
        out = bicycle.rk4_trajectory(
            x0, inputs, dt, p.wheelbase,
            lambda v, phi: tricycle.midpoint_speeds(v, phi, p.track, p.wheelbase))
        return rk4_states(self.rhs, x0, inputs, dt) if out is None else out

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose of the ``base`` site and the steering angle."""
        return np.append(base_pose(model, data), data.joint("steer").qpos[0])


@dataclass
class FreeWheelProbe:
    """The free rear wheel's rate against the ICR prediction, after 1 s, when rolling."""

    params: TricycleParams
    wheel_dofs: tuple[int, int]
    steer_qpos: int
    errors: list[float] = field(default_factory=list)

    def observe(self, sample: Sample) -> None:
        """Relative error ``(θ̇_R − θ̇_R,ICR) / θ̇_R,ICR`` at this step."""
        rates = sample.data.qvel[list(self.wheel_dofs)]
        if sample.t <= 1.0 or abs(rates[0]) <= 1.0:
            return
        p = self.params
        k = p.track / (2 * p.wheelbase) * np.tan(sample.data.qpos[self.steer_qpos])
        predicted = rates[0] * (1 + k) / (1 - k)
        self.errors.append((rates[1] - predicted) / predicted)

    def metrics(self) -> list[Metric]:
        """RMS relative error, reported."""
        if not self.errors:
            return []
        return [Metric("free-wheel rate error vs ICR (RMS)", 100.0 * rms(self.errors), "%")]


def free_wheel_probe(scenario: Scenario, model: mujoco.MjModel, adapter: Adapter,
                     targets: Mapping[str, Target]) -> FreeWheelProbe | None:
    """The free-wheel probe of a kinematic run (an open differential obeys it too)."""
    if not isinstance(adapter, TricycleKinematics):
        return None
    dofs = tuple(int(model.jnt_dofadr[model.joint(j).id]) for j in adapter.wheel_joints[:2])
    return FreeWheelProbe(adapter.params, (dofs[0], dofs[1]),
                          int(model.jnt_qposadr[model.joint("steer").id]))


def kinematic_adapter(scenario: Scenario, model: mujoco.MjModel,
                      params: RobotParams | None) -> TricycleKinematics:
    """The kinematic tricycle model."""
    return TricycleKinematics(params_or_default(params, TricycleParams))


TARGETS: Mapping[str, Target] = req.vehicle_targets(0.5)

#: The 0.6 rad turn's position requirement is open over its family: its fastest, tightest
#: draws (up to 1.2 times the speed and the steering: the largest lateral acceleration)
#: miss it, with lateral slip several times the other turns' (the families table), which
#: the kinematic model leaves out.
SHARP_TURN_OPEN = {"worst position error": "the family's fastest, tightest draws miss it; "
                   "their lateral slip is several times the gentler turns' (spread in the "
                   "families table), which the kinematic model leaves out",
                   **{f"lateral slip RMS, {w}": "the floor pairs' friction is viscous "
                      "(damping 1/Δt, docs/floor-contact.md): the wheels creep sideways in "
                      "proportion to the cornering force, which the fastest, tightest draws "
                      "raise past the bound" for w in ("rear_left_wheel", "rear_right_wheel",
                                                        "front_wheel")}}

SCENARIOS = (
    # The driven wheel is the inner one in left turns: speed first, then steering, so
    # that the midpoint's acceleration v_L/(1 − k) stays below the traction limit.
    # Families: speed and steering (rate, so angle) ±20 %; a steady turn's length ±20 %.
    # The tightest turn's spread is not small (python -m wmr_mujoco.bench.family_spread):
    # 20 draws, and its position requirement open over them (SHARP_TURN_OPEN). Nor is
    # the 0.4 rad turn's (its front wheel's lateral slip at 1.2 times the speed and
    # steering is beyond half its target): 20 draws.
    *(Scenario(NAME, f"steady turn {phi:g} rad", (const(1.0, 1.0), steer_to(phi, 1.0)),
               family=Family((var.channel(0), var.channel(1),
                              var.around(var.DURATION, 10.0)),
                             var.DYNAMIC_DRAWS if phi >= 0.4 else var.KINEMATIC_DRAWS),
               open_targets=SHARP_TURN_OPEN if sharp else {})
      for phi, sharp in ((0.2, False), (0.4, False), (0.6, True))),
    # Steer to +0.5 rad, one full circle (about 4.5 s), steer through to −0.5, a second.
    # Its spread is not small (the front wheel's lateral slip and the position at 1.2
    # times the speed and steering are beyond half their targets): 20 draws.
    Scenario(NAME, "figure eight", (const(1.0, 1.0), pulses(
        (1.0, 1.5, 1.0), (5.7, 6.7, -1.0))), duration=12.0, family=Family(
        (var.channel(0), var.channel(1)), var.DYNAMIC_DRAWS)),
)

def left_wheel_speed(adapter: TricycleKinematics, u: np.ndarray,
                     steer: np.ndarray) -> np.ndarray:
    """``(v, ω) -> (v_L, ω)``: ``v_L = v (1 − k)`` at the steering target (module docstring)."""
    p = adapter.params
    v_left, _ = tricycle.rear_wheel_speeds(u[0], steer[0], p.track, p.wheelbase)
    return np.array([v_left, u[1]])


#: Driven by ``(v, φ)``: speed of the rear-axle midpoint and steering angle (servoed);
#: the driven left wheel gets ``v (1 − k)``.
COMMAND = RateCommand(("v", "steer"), ("m/s", "rad"),
                      wheels=("rear_left_wheel", "rear_right_wheel", "front_wheel"),
                      steers=("steer",), servo=(Servo(1, "steer", 3),),
                      adjust=left_wheel_speed,
                      kinematics=lambda p: TricycleKinematics(
                          params_or_default(p, TricycleParams)))

SPEC = RobotSpec(
    name=NAME,
    description="tricycle on a free joint: steered front wheel, left rear wheel driven, "
                "right rear wheel free (or an open differential)",
    params_type=TricycleParams, build=builder.build, folder="tricycle",
    robot_file="tricycle.xml",
    adapters={ScenarioKind.KINEMATIC: kinematic_adapter},
    probes=(free_wheel_probe,),
    targets=TARGETS, scenarios=SCENARIOS, demo_scenario="figure eight",
    render_scenario="figure eight", picture=Picture(joint_angles={"steer": 0.35}),
    command=COMMAND,
    scene_extras=wheel_floor_pairs(builder.build),
    learning=Learning("Tricycle", steer_arm="wheelbase"),
)
