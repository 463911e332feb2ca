"""The planar bicycle held upright (lecture section 2): driven rear wheel, steered fork.

Kinematic inputs ``(v_r, ω)``: rear-wheel ground speed and steering rate; state
``(x, y, ψ, φ)`` of the rear-axle midpoint, heading and steering angle.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import ClassVar

import mujoco
import numpy as np

from wmr_mujoco.analytic import bicycle
from wmr_mujoco.analytic.integrate import rk4_states
from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.builders.wheel_pairs import wheel_floor_pairs
from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.robots import requirements as req
from wmr_mujoco.robots.bicycle import builder
from wmr_mujoco.robots.bicycle.params import BicycleParams
from wmr_mujoco.robots.learning import NO_RADIUS_BANDS, Learning
from wmr_mujoco.robots.spec import Clip, Picture, RobotSpec
from wmr_mujoco.validation import variations as var
from wmr_mujoco.validation.adapters import POSE_UNITS, base_pose
from wmr_mujoco.validation.command import RateCommand, Servo
from wmr_mujoco.validation.family import Family
from wmr_mujoco.validation.metrics import Target
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.signals import const, pulses, steer_to

NAME = "bicycle"


@dataclass(frozen=True)
class BicycleKinematics:
    """Bicycle: ``x = (x, y, ψ, φ)``; controls ``(v_r/R_r, ω)``."""

    #: ``sim_state`` reads the pose and joint positions alone (the runner's frames only).
    frames_only: ClassVar[bool] = True

    params: BicycleParams
    mode: ActuationMode = ActuationMode.RATE
    state_names: tuple[str, ...] = ("x", "y", "heading", "steer")
    state_units: tuple[str, ...] = (*POSE_UNITS, "rad")
    wheel_joints: tuple[str, ...] = ("rear_wheel", "front_wheel")
    lateral_wheels: tuple[str, ...] = ("rear_wheel", "front_wheel")

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """``(θ̇_r, ω) = (v_r / R_r, ω)``."""
        return np.array([u[0] / self.params.rear_wheel.radius, u[1]])

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Bicycle kinematics (:func:`wmr_mujoco.analytic.bicycle.rates`)."""
        return bicycle.rates(x, u, self.params.wheelbase)

    def trajectory(self, x0: np.ndarray, inputs: np.ndarray, dt: float) -> np.ndarray:
        """RK4 on :meth:`rhs` over every step at once (the floats of step after step).

        :func:`wmr_mujoco.analytic.bicycle.rk4_trajectory`, or the steps one by one where
        it declines (a stage that is not finite: they raise there).
        """
        out = bicycle.rk4_trajectory(x0, inputs, dt, self.params.wheelbase)
        return rk4_states(self.rhs, x0, inputs, dt) if out is None else out

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose of the ``base`` site and the steering angle."""
        return np.append(base_pose(model, data), data.joint("steer").qpos[0])


def kinematic_adapter(scenario: Scenario, model: mujoco.MjModel,
                      params: RobotParams | None) -> BicycleKinematics:
    """The kinematic bicycle model."""
    return BicycleKinematics(params_or_default(params, BicycleParams))


TARGETS: Mapping[str, Target] = req.vehicle_targets(0.5)

SCENARIOS = (
    # Families: speed and steering (rate, so angle) ±20 %; a steady turn's length ±20 %.
    # The tightest turn's spread is not small (its front wheel's lateral slip at 1.2
    # times the speed and steering is beyond half its target; python -m
    # wmr_mujoco.bench.family_spread bicycle): 20 draws.
    *(Scenario(NAME, f"steady turn {phi:g} rad", (const(2.0, 1.0), steer_to(phi)),
               family=Family((var.channel(0), var.channel(1),
                              var.around(var.DURATION, 10.0)),
                             var.DYNAMIC_DRAWS if phi >= 0.5 else var.KINEMATIC_DRAWS))
      for phi in (0.15, 0.3, 0.5)),
    Scenario(NAME, "steering ramp", (const(2.0, 1.0), const(0.05)), family=Family(
        (var.channel(0), var.channel(1)), var.KINEMATIC_DRAWS)),
    Scenario(NAME, "lane change", (const(2.0, 1.0), pulses(
        (2.0, 2.5, 0.4), (2.5, 3.5, -0.4), (3.5, 4.0, 0.4))), family=Family(
        (var.channel(0), var.channel(1)), var.KINEMATIC_DRAWS)),
)

#: Driven by ``(v_r, φ)``: rear-wheel ground speed and steering angle (servoed).
COMMAND = RateCommand(("v", "steer"), ("m/s", "rad"), wheels=("rear_wheel", "front_wheel"),
                      steers=("steer",), servo=(Servo(1, "steer", 3),),
                      kinematics=lambda p: BicycleKinematics(
                          params_or_default(p, BicycleParams)))

SPEC = RobotSpec(
    name=NAME,
    description="planar bicycle held upright: driven rear wheel, steered front fork",
    params_type=BicycleParams, build=builder.build, folder="bicycle",
    robot_file="bicycle.xml",
    adapters={ScenarioKind.KINEMATIC: kinematic_adapter},
    targets=TARGETS, scenarios=SCENARIOS, demo_scenario="lane change",
    bench_scenario="steady turn 0.3 rad", render_scenario="lane change",
    picture=Picture(joint_angles={"steer": 0.35}), clips=(Clip(duration=5.0),),
    command=COMMAND,
    scene_extras=wheel_floor_pairs(builder.build),
    # Planar model: its joints hold the frame level (no pitch), so wheels of different
    # radii would lift one of them off the floor: no radius band.
    learning=Learning("Bicycle", scale=3.0, max_curvature=0.5, bands=NO_RADIUS_BANDS,
                      steer_arm="wheelbase"),
)
