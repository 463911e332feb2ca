"""The differential drive: two driven wheels on one axle and a passive ball caster.

Kinematic inputs ``(v, ω)``: speed and yaw rate of the axle midpoint; the wheels roll at
``v ∓ ω b/2`` (left, right), so the controls are ``(v_L/R, v_R/R)``; state ``(x, y, ψ)``
of the midpoint, the unicycle (:mod:`wmr_mujoco.robots.diffdrive.analytic`). Campion class
(2,0), computed from the model by :mod:`wmr_mujoco.models.classify`.

Turning in place the midpoint does not move; that run is judged on its worst centre
drift against 0.5 % of the arc each wheel rolls (:func:`wheel_arc`). The ball caster's
drag is a measurement scenario (:mod:`.caster_drag`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import ClassVar

import mujoco
import numpy as np

from wmr_mujoco.analytic.planar import twist_step
from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.builders.wheel_pairs import wheel_floor_pairs
from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.robots import requirements as req
from wmr_mujoco.robots.diffdrive import analytic as diffdrive
from wmr_mujoco.robots.diffdrive import builder, caster_drag
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams
from wmr_mujoco.robots.learning import Learning
from wmr_mujoco.robots.spec import RobotSpec
from wmr_mujoco.validation import metrics as mt
from wmr_mujoco.validation import variations as var
from wmr_mujoco.validation.adapters import POSE_UNITS, base_pose
from wmr_mujoco.validation.command import RateCommand
from wmr_mujoco.validation.family import Family
from wmr_mujoco.validation.metrics import Target
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.signals import Sine, const

NAME = "diffdrive"


@dataclass(frozen=True)
class DiffDriveKinematics:
    """Unicycle of the axle midpoint: ``x = (x, y, ψ)``, ``u = (v, ω)``."""

    #: ``sim_state`` reads the pose and joint positions alone (the runner's frames only).
    frames_only: ClassVar[bool] = True

    params: DiffDriveParams
    mode: ActuationMode = ActuationMode.RATE
    state_names: tuple[str, ...] = ("x", "y", "heading")
    state_units: tuple[str, ...] = POSE_UNITS
    wheel_joints: tuple[str, ...] = ("left_wheel", "right_wheel")
    lateral_wheels: tuple[str, ...] = ("left_wheel", "right_wheel")

    def wheel_speeds(self, u: np.ndarray) -> np.ndarray:
        """Ground speeds ``(v_L, v_R) = (v − ω b/2, v + ω b/2)``."""
        return np.array(diffdrive.wheel_speeds(u[0], u[1], self.params.track))

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Wheel-rate servo targets ``(v_L/R, v_R/R)``."""
        return self.wheel_speeds(u) / self.params.wheel.radius

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """``ẋ = v cos ψ, ẏ = v sin ψ, ψ̇ = ω`` from the wheel speeds."""
        return diffdrive.rates(x, self.wheel_speeds(u), self.params.track)

    def exact_step(self, x: np.ndarray, u: np.ndarray, dt: float) -> np.ndarray:
        """``x`` after ``dt`` of the held ``u``: the arc of the wheels' twist ``(v, 0, ω)``.

        :func:`~wmr_mujoco.analytic.planar.twist_step` of the twist :meth:`rhs` uses, what
        RK4 on it approximates (error per step ``v ω⁴ Δt⁵ / 2880``: below round-off at
        the validation's steps).
        """
        v, omega = diffdrive.twist(*self.wheel_speeds(u), self.params.track)
        return twist_step(x, (v, 0.0, omega), dt)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose of the ``base`` site (the axle midpoint)."""
        return base_pose(model, data)


def kinematic_adapter(scenario: Scenario, model: mujoco.MjModel,
                      params: RobotParams | None) -> DiffDriveKinematics:
    """The unicycle model of the differential drive."""
    return DiffDriveKinematics(params_or_default(params, DiffDriveParams))


def wheel_arc(scenario: Scenario, track: float, dt: float = 1e-3) -> float:
    """Arc each wheel rolls turning in place: ``(b/2) ∫ |ω| dt`` over the run, m."""
    t = np.arange(0.0, scenario.duration, dt)
    return 0.5 * track * float(np.sum(np.abs([scenario.input_at(ti)[1] for ti in t])) * dt)


SPIN = Scenario(NAME, "spin in place", (const(0.0), const(1.5, 0.5)), duration=2.0,
                description="turn in place at 1.5 rad/s: judged on the centre's drift",
                family=Family((var.channel(1), var.around(var.DURATION, 2.0)),
                              var.KINEMATIC_DRAWS))

SCENARIOS = (
    # Families: speed and turn rate ±20 %, run length ±20 % where the inputs hold.
    Scenario(NAME, "straight", (const(0.5, 0.5), const(0.0)), duration=2.0, family=Family(
        (var.channel(0), var.around(var.DURATION, 2.0)), var.KINEMATIC_DRAWS)),
    Scenario(NAME, "arc", (const(0.5, 0.5), const(0.5, 0.5)), duration=3.0, family=Family(
        (var.channel(0), var.channel(1), var.around(var.DURATION, 3.0)),
        var.KINEMATIC_DRAWS)),
    SPIN,
    # ω = ω₀ sin(2πt/T) at constant v: the heading swings ±ω₀T/2π and returns, two
    # loops traced in opposite senses: a figure eight.
    # Its spread is not small (bench.family_spread): 20 draws.
    Scenario(NAME, "figure eight", (const(0.5, 0.5), Sine(1.5, 5.0)), duration=5.0,
             family=Family((var.channel(0), var.channel(1)), var.DYNAMIC_DRAWS)),
    Scenario(NAME, "caster drag", kind=ScenarioKind.MEASUREMENT, duration=caster_drag.STEADY,
             settle=caster_drag.SETTLE, evaluate=caster_drag.evaluate,
             description="the ball caster's drag, freely rolling and with MuJoCo's "
                         "rolling friction"),
)

_SPIN_ARC = wheel_arc(SPIN, DiffDriveParams().track)

TARGETS: Mapping[str, Target] = {
    **req.vehicle_targets(0.5),
    mt.CENTRE_DRIFT_M: Target.requirement(
        0.005 * _SPIN_ARC, f"{req.SOURCE}: 0.5 % of path; turning in place the path is the "
                           f"arc each wheel rolls, (b/2)∫|ω|dt = {_SPIN_ARC:.3f} m"),
}

#: Driven by ``(v, ω)``, the unicycle's inputs.
COMMAND = RateCommand(("v", "omega"), ("m/s", "rad/s"), wheels=("left_wheel", "right_wheel"),
                      kinematics=lambda p: DiffDriveKinematics(
                          params_or_default(p, DiffDriveParams)))

SPEC = RobotSpec(
    name=NAME,
    description="differential drive: two driven wheels on one axle and a passive ball "
                "caster; Campion class (2,0)",
    params_type=DiffDriveParams, build=builder.build, folder=NAME, robot_file="diffdrive.xml",
    adapters={ScenarioKind.KINEMATIC: kinematic_adapter},
    targets=TARGETS, scenarios=SCENARIOS, demo_scenario="figure eight",
    bench_scenario="figure eight", render_scenario="figure eight", command=COMMAND,
    scene_extras=wheel_floor_pairs(builder.build),
    learning=Learning("DiffDrive", scale=1.0, max_curvature=1.5),
)
