"""Campion class (1,2): two centred steerable driven wheels and a ball caster.

Rate inputs ``(v₁, ω₁, ω₂)``: ground speed of the front wheel and both steering rates.
One instantaneous centre of rotation needs the rear wheel at
``v₂ = v₁ cos β₁ / cos β₂`` (:func:`wmr_mujoco.robots.steered.analytic.double_rear_speed`), from
the analytic steering angles of the open-loop schedule; controls, in actuator order,
``(v₁/R, ω₁, v₂/R, ω₂)``. State ``(x, y, ψ, β₁, β₂)`` of the midpoint between the
steering axes (the ``base`` site).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import mujoco
import numpy as np

from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.builders.wheel_pairs import wheel_floor_pairs
from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.robots import requirements as req
from wmr_mujoco.robots.double_steer import builder
from wmr_mujoco.robots.double_steer.params import DoubleSteerParams
from wmr_mujoco.robots.learning import Learning
from wmr_mujoco.robots.spec import Picture, RobotSpec
from wmr_mujoco.robots.steered import analytic as steered
from wmr_mujoco.validation import floor_family
from wmr_mujoco.validation import variations as var
from wmr_mujoco.validation.adapters import POSE_UNITS, base_pose
from wmr_mujoco.validation.command import RateCommand, Servo
from wmr_mujoco.validation.family import Family
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.signals import const, steer_to

NAME = "double_steer"


@dataclass(frozen=True)
class DoubleSteerKinematics:
    """Two steered wheels, one ICR: ``x = (x, y, ψ, β₁, β₂)``, ``u = (v₁, ω₁, ω₂)``."""

    #: ``sim_state`` reads the pose and joint positions alone (the runner's frames only).
    frames_only: ClassVar[bool] = True

    params: DoubleSteerParams
    mode: ActuationMode = ActuationMode.RATE
    state_names: tuple[str, ...] = ("x", "y", "heading", "front steer", "rear steer")
    state_units: tuple[str, ...] = (*POSE_UNITS, "rad", "rad")
    wheel_joints: tuple[str, ...] = ("front_wheel", "rear_wheel")
    lateral_wheels: tuple[str, ...] = ("front_wheel", "rear_wheel")

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """``(v₁/R, ω₁, v₂/R, ω₂)`` with ``v₂ = v₁ cos β₁ / cos β₂``."""
        x = analytic_state
        v2 = steered.double_rear_speed(u[0], x[3], x[4])
        r = self.params.wheel.radius
        return np.array([u[0] / r, u[1], v2 / r, u[2]])

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Kinematics of :func:`wmr_mujoco.robots.steered.analytic.double_rates`."""
        return steered.double_rates(x, u, self.params.half_wheelbase)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose of ``base`` and both steering angles."""
        return np.append(base_pose(model, data), [data.joint("front_steer").qpos[0],
                                                  data.joint("rear_steer").qpos[0]])


def kinematic_adapter(scenario: Scenario, model: mujoco.MjModel,
                      params: RobotParams | None) -> DoubleSteerKinematics:
    """The one-ICR kinematic model of the (1,2) robot."""
    return DoubleSteerKinematics(params_or_default(params, DoubleSteerParams))


#: The tight turn's position requirement is open over its family: its spread is not
#: small (20 draws), and the shorter runs at up to 1.2 times the speed and steering miss
#: it, which the kinematic model does not yet explain (the families table shows it).
TIGHT_TURN_OPEN = {"worst position error": "the family's shorter runs at up to 1.2 times "
                   "the speed and steering miss it; not yet explained by the kinematic "
                   "model (spread in the families table)"}

SCENARIOS = (
    # Steering first (0.5 s at rest), then speed over a 0.5 s ramp: crabbing (both
    # wheels parallel, a translation) and turning about a near ICR (opposite angles).
    # Families: speed and both steering angles by one factor ±20 % (one factor keeps
    # the crab's angles equal and the tight turn's opposite), the length ±20 %.
    Scenario(NAME, "crab 0.5 rad", (const(0.4, 0.5), steer_to(0.5), steer_to(0.5)),
             duration=2.5, family=Family(
                 (var.speeds(), var.around(var.DURATION, 2.5)),
                 var.KINEMATIC_DRAWS)),
    Scenario(NAME, "tight turn ±1 rad", (const(0.3, 0.5), steer_to(1.0), steer_to(-1.0)),
             duration=3.0, family=Family(
                 (var.speeds(), var.around(var.DURATION, 3.0)), var.DYNAMIC_DRAWS),
             open_targets=TIGHT_TURN_OPEN),
)

#: Driven by ``(v₁, β₁, β₂)``: front wheel ground speed and both steering angles
#: (servoed); the rear wheel's speed for one ICR comes from the measured angles.
COMMAND = RateCommand(("v", "front_steer", "rear_steer"), ("m/s", "rad", "rad"),
                      wheels=("front_wheel", "rear_wheel"),
                      steers=("front_steer", "rear_steer"),
                      servo=(Servo(1, "front_steer", 3), Servo(2, "rear_steer", 4)),
                      state_dependent=True,
                      kinematics=lambda p: DoubleSteerKinematics(
                          params_or_default(p, DoubleSteerParams)))

#: Over its random steps a draw may roll the robot over (the chassis tilt reported beside
#: reaches a half turn). The random steering rates walk the rear steering to its joint
#: limit, where one ICR asks the rear wheel for ``v₁ cos β₁ / cos β₂``, several times the
#: front's speed, reversed from one control period to the next; the chassis, whose CoM
#: lies between the wheels' line and the caster, rolls over about that line on the side
#: away from the caster. Physics, not a contact artefact: its wheels leave the floor for
#: real, and the robot, upside down, lands on its wheels' tops, an impact that presses a
#: wheel deeper than the driving contact does (the draws that stay upright keep within
#: the bound: tests/robots/double_steer/test_double_steer.py).
ROLL_OVER = ("a draw rolls the robot over (chassis tilt, reported beside): the rear "
             "steering at its limit, one ICR asks the rear wheel for several times the "
             "front's speed, reversed every control period")
FLOOR_OPEN = {floor_family.NAME: {
    floor_family.OVER_RUN: f"{ROLL_OVER}; its wheels leave the floor for real",
    floor_family.DEPTH: f"{ROLL_OVER}; upside down, it lands on its wheels' tops, an "
                        "impact, not the driving contact (draws that stay upright keep "
                        "within the bound)"}}

SPEC = RobotSpec(
    name=NAME,
    description="two centred steerable driven wheels and a ball caster; Campion class "
                "(1,2)",
    params_type=DoubleSteerParams, build=builder.build, folder=NAME,
    robot_file="double_steer.xml",
    adapters={ScenarioKind.KINEMATIC: kinematic_adapter},
    targets=req.vehicle_targets(0.5), scenarios=SCENARIOS,
    bench_scenario="tight turn ±1 rad", render_scenario="tight turn ±1 rad",
    picture=Picture(joint_angles={"front_steer": 0.35, "rear_steer": -0.35}),
    command=COMMAND,
    scene_extras=wheel_floor_pairs(builder.build), open_targets=FLOOR_OPEN,
    learning=Learning("DoubleSteer", steer_arm="half_wheelbase"),
)
