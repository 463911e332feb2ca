"""Campion class (2,1): one centred steerable driven wheel and two ball casters.

Rate inputs ``(v_w, ω)``: ground speed of the steered wheel and its steering rate;
controls ``(v_w/R, ω)``. Kinematics alone leave the yaw free (δm = 2: the wheel's one
constraint fixes neither heading nor yaw rate), so the analytic model is the Chaplygin
sleigh's dynamics (:mod:`wmr_mujoco.robots.steered.analytic`): state ``(x, y, ψ, β, p)`` of the
chassis origin P (the ``base`` site, above the steering axis), with ``p`` the momentum
conjugate to the free yaw. The run is a rate-input (kinematic-kind) scenario through
that dynamic model.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import mujoco
import numpy as np

from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.builders.wheel_pairs import wheel_floor_pairs
from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.robots import requirements as req
from wmr_mujoco.robots.learning import Learning
from wmr_mujoco.robots.single_steer import builder
from wmr_mujoco.robots.single_steer.inertia import sleigh_inertia
from wmr_mujoco.robots.single_steer.params import SingleSteerParams
from wmr_mujoco.robots.spec import Picture, RobotSpec
from wmr_mujoco.robots.steered import analytic as steered
from wmr_mujoco.validation import variations as var
from wmr_mujoco.validation.adapters import POSE_UNITS, base_pose
from wmr_mujoco.validation.command import RateCommand, Servo
from wmr_mujoco.validation.family import Family
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.signals import Sine, const, steer_to

NAME = "single_steer"


@dataclass(frozen=True)
class SingleSteerSleigh:
    """Sleigh dynamics of P: ``x = (x, y, ψ, β, p)``; ``u = (v_w, ω)``."""

    params: SingleSteerParams
    mode: ActuationMode = ActuationMode.RATE
    state_names: tuple[str, ...] = ("x", "y", "heading", "steer", "momentum")
    state_units: tuple[str, ...] = (*POSE_UNITS, "rad", "kg·m²/s")
    wheel_joints: tuple[str, ...] = ("drive_wheel",)
    lateral_wheels: tuple[str, ...] = ("drive_wheel",)

    @cached_property
    def inertia(self) -> steered.SleighInertia:
        """Mass data of the sleigh equations."""
        return sleigh_inertia(self.params)

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """``(v_w/R, ω)``: wheel-rate and steering-rate servo targets."""
        return np.array([u[0] / self.params.wheel.radius, u[1]])

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """The sleigh equations (:func:`wmr_mujoco.robots.steered.analytic.single_rates`)."""
        return steered.single_rates(x, u, self.inertia)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose of ``base``, steering angle and the yaw momentum from the velocities."""
        steer = data.joint("drive_steer")
        v_w = data.joint("drive_wheel").qvel[0] * self.params.wheel.radius
        # The free joint's angular velocity is in the chassis frame; its z is the yaw rate
        # of the level chassis.
        yaw_rate = data.joint("chassis").qvel[5]
        mom = steered.single_momentum(yaw_rate, v_w, steer.qpos[0], steer.qvel[0],
                                      self.inertia)
        return np.append(base_pose(model, data), [steer.qpos[0], mom])


def sleigh_adapter(scenario: Scenario, model: mujoco.MjModel,
                   params: RobotParams | None) -> SingleSteerSleigh:
    """The Chaplygin-sleigh model of the (2,1) robot."""
    return SingleSteerSleigh(params_or_default(params, SingleSteerParams))


SCENARIOS = (
    # The casters lead, the steered wheel pushes from behind: start straight, then
    # steer 0.5 rad in 0.5 s while rolling (the chassis yaws, the sleigh's free mode).
    # Families: speed and steering ±20 %; the crab's length ±20 %.
    Scenario(NAME, "crab 0.5 rad", (const(0.4, 0.5), steer_to(0.5, 1.0)), duration=3.0,
             family=Family((var.channel(0), var.channel(1), var.around(var.DURATION, 3.0)),
                           var.KINEMATIC_DRAWS)),
    Scenario(NAME, "slalom", (const(0.4, 0.5), Sine(0.6, 3.0)), duration=4.0,
             family=Family((var.channel(0), var.channel(1)), var.KINEMATIC_DRAWS)),
)

#: Driven by ``(v_w, β)``: the steered wheel's ground speed and steering angle (servoed);
#: the yaw is free (δm = 2), so no yaw rate can be commanded.
COMMAND = RateCommand(("v", "steer"), ("m/s", "rad"), wheels=("drive_wheel",),
                      steers=("drive_steer",), servo=(Servo(1, "drive_steer", 3),),
                      kinematics=lambda p: SingleSteerSleigh(
                          params_or_default(p, SingleSteerParams)))

SPEC = RobotSpec(
    name=NAME,
    description="one centred steerable driven wheel and two ball casters; Campion class "
                "(2,1)",
    params_type=SingleSteerParams, build=builder.build, folder=NAME,
    robot_file="single_steer.xml",
    adapters={ScenarioKind.KINEMATIC: sleigh_adapter},
    targets=req.vehicle_targets(0.5), scenarios=SCENARIOS, bench_scenario="slalom",
    render_scenario="slalom", picture=Picture(joint_angles={"drive_steer": 0.35}),
    command=COMMAND,
    scene_extras=wheel_floor_pairs(builder.build),
    # Its yaw is free (a Chaplygin sleigh: the steered wheel's one constraint fixes
    # neither heading nor yaw rate), so its goal is a position: any heading counts.
    learning=Learning("SingleSteer", task_options={"GoToGoal": {"heading_tolerance": 4.0}}),
)
