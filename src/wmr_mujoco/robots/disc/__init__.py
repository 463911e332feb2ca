"""The single steerable disc on a vertical mount (lecture section 1).

Kinematic inputs ``(v, ω)``: wheel ground speed ``R θ̇`` and steering rate; state
``(x, y, φ)`` of the unicycle model. Torque inputs ``(τ_wheel, τ_steer)``: state
``(s, ṡ)``, distance and speed along the heading, against ``s̈ = τR / (J + mR²)``,
with ``m``, ``J`` (body inertia plus armature) and ``R`` from the compiled model.
Measurement scenarios (:mod:`.sliding`): the wheel above its traction limit.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import ClassVar

import mujoco
import numpy as np

from wmr_mujoco.analytic import unicycle
from wmr_mujoco.analytic.planar import twist_step
from wmr_mujoco.analytic.wheel_dynamics import WheelDynamics
from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.robots import requirements as req
from wmr_mujoco.robots.disc import builder, sliding
from wmr_mujoco.robots.disc.params import DiscParams
from wmr_mujoco.robots.disc.wheel import mounted_wheel
from wmr_mujoco.robots.learning import Learning
from wmr_mujoco.robots.spec import Clip, Picture, RobotSpec
from wmr_mujoco.validation import variations as var
from wmr_mujoco.validation.adapters import POSE_UNITS, base_pose
from wmr_mujoco.validation.command import RateCommand
from wmr_mujoco.validation.family import Family
from wmr_mujoco.validation.metrics import Metric, Target, Trace
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario, ScenarioKind
from wmr_mujoco.validation.signals import Sine, const

NAME = "disc"
#: Key of the rolling-acceleration target.
ACCELERATION_PCT = "rolling acceleration error %"


@dataclass(frozen=True)
class DiscKinematics:
    """Disc: ``x = (x, y, φ)``; controls ``(v/R, ω)``."""

    #: ``sim_state`` reads the pose and joint positions alone (the runner's frames only).
    frames_only: ClassVar[bool] = True

    params: DiscParams
    mode: ActuationMode = ActuationMode.RATE
    state_names: tuple[str, ...] = ("x", "y", "heading")
    state_units: tuple[str, ...] = POSE_UNITS
    wheel_joints: tuple[str, ...] = ("wheel",)
    lateral_wheels: tuple[str, ...] = ("wheel",)

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """``(θ̇, ω) = (v / R, ω)``."""
        return np.array([u[0] / self.params.wheel.radius, u[1]])

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Unicycle ``(ẋ, ẏ, φ̇) = (v cos φ, v sin φ, ω)``."""
        return unicycle.rates(x, u)

    def exact_step(self, x: np.ndarray, u: np.ndarray, dt: float) -> np.ndarray:
        """``x`` after ``dt`` of the held ``u``: the arc of the body twist ``(v, 0, ω)``.

        :func:`~wmr_mujoco.analytic.planar.twist_step`, what RK4 on :meth:`rhs`
        approximates (its error per step ``v ω⁴ Δt⁵ / 2880``, Simpson's rule on
        ``cos φ``: below round-off at the validation's steps).
        """
        return twist_step(x, (u[0], 0.0, u[1]), dt)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose of the ``base`` site."""
        return base_pose(model, data)


@dataclass(frozen=True)
class DiscDynamics:
    """Disc under wheel torque: ``x = (s, ṡ)`` distance and speed along the heading.

    Analytic model :class:`WheelDynamics` of the compiled model
    (:func:`~wmr_mujoco.robots.disc.wheel.mounted_wheel`): the moving mass (disc +
    carriage) and the inertia about the wheel hinge including the armature.
    """

    wheel: WheelDynamics
    mode: ActuationMode = ActuationMode.TORQUE
    state_names: tuple[str, ...] = ("distance", "speed")
    state_units: tuple[str, ...] = ("m", "m/s")
    wheel_joints: tuple[str, ...] = ("wheel",)
    lateral_wheels: tuple[str, ...] = ("wheel",)

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Torques as given."""
        return np.asarray(u, float)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """``(ṡ, s̈) = (ṡ, τR / (J + mR²))``."""
        return np.array([x[1], self.wheel.rolling_acceleration(u[0])])

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Distance and speed of the carriage along the steering heading."""
        heading = data.joint("steer").qpos[0]
        direction = np.array([np.cos(heading), np.sin(heading)])
        return np.array([data.qpos[:2] @ direction, data.qvel[:2] @ direction])


def kinematic_adapter(scenario: Scenario, model: mujoco.MjModel,
                      params: RobotParams | None) -> DiscKinematics:
    """The unicycle model of the disc."""
    return DiscKinematics(params_or_default(params, DiscParams))


def dynamic_adapter(scenario: Scenario, model: mujoco.MjModel,
                    params: RobotParams | None) -> DiscDynamics:
    """The single-wheel Lagrange model of the compiled disc (J includes the armature)."""
    return DiscDynamics(mounted_wheel(model))


def judge_rolling(scenario: Scenario, trace: Trace, adapter: DiscDynamics,
                  targets: Mapping[str, Target]) -> list[Metric]:
    """Rolling acceleration: slope of the measured speed (after 0.5 s) against the model.

    The slope is a least-squares fit over the whole steady part of the run (after 0.5 s,
    or after a longer drawn lead-in), so it is judged on every sample, not on one
    instant; the torque is the one held there.

    Raises:
        ValueError: the run ends before two samples of its steady part (duration ≤ 0.5 s).
    """
    tr = trace.arrays()
    t, sim, ana = tr["time"], tr["sim"], tr["analytic"]
    steady = t > max(0.5, scenario.value(var.LEAD_IN, 0.0))
    if np.count_nonzero(steady) < 2:
        raise ValueError(f"{scenario.key}: duration = {scenario.duration:g} s; the rolling "
                         "acceleration is fitted after 0.5 s, give a longer run")
    measured = float(np.polyfit(t[steady], sim[steady, 1], 1)[0])
    torque = scenario.input_at(scenario.duration)[0]
    expected = adapter.wheel.rolling_acceleration(torque)
    return [
        Metric("rolling acceleration error", 100.0 * (measured - expected) / expected, "%",
               targets.get(ACCELERATION_PCT)),
        Metric("rolling acceleration (MuJoCo)", measured, "m/s²"),
        Metric("rolling acceleration τR/(J+mR²)", expected, "m/s²"),
        Metric("worst speed error", float(np.max(np.abs(sim[:, 1] - ana[:, 1]))), "m/s"),
        Metric("traction limit margin", adapter.wheel.max_rolling_torque / abs(torque), "×",
               note="largest torque without slip, μ N R (J + mR²)/(mR²), over the torque"),
    ]


TARGETS: Mapping[str, Target] = {
    **req.vehicle_targets(0.5),
    ACCELERATION_PCT: Target.requirement(1.0, f"{req.SOURCE}: single-wheel acceleration "
                                              "within 1 % of τR/(J + mR²)"),
}

def _on_model(measure: Callable[[mujoco.MjModel], MeasurementResult]
              ) -> Callable[[Scenario, RobotParams | None], MeasurementResult]:
    """A measurement scenario's ``evaluate``: ``measure`` on the disc built from params."""
    def evaluate(scenario: Scenario, params: RobotParams | None) -> MeasurementResult:
        from wmr_mujoco.models.loading import load

        return measure(load(SPEC, params))
    return evaluate


SCENARIOS = (
    # Families: speed and steering rate ±20 %, run length ±20 % where the inputs hold;
    # the torque ±20 %, from a step or a ramp of up to 0.2 s (the disc's wheel is
    # round: no phase to vary).
    Scenario(NAME, "straight", (const(1.0, 0.5), const(0.0)), family=Family(
        (var.channel(0), var.around(var.DURATION, 10.0)), var.KINEMATIC_DRAWS)),
    Scenario(NAME, "constant steering", (const(1.0, 0.5), const(0.5)), family=Family(
        (var.channel(0), var.channel(1), var.around(var.DURATION, 10.0)),
        var.KINEMATIC_DRAWS)),
    Scenario(NAME, "sinusoidal steering", (const(1.0, 0.5), Sine(0.8, 4.0)), family=Family(
        (var.channel(0), var.channel(1)), var.KINEMATIC_DRAWS)),
    Scenario(NAME, "torque", (const(0.3), const(0.0)), duration=2.0,
             kind=ScenarioKind.DYNAMIC, family=Family(
                 (var.speeds(), var.around(var.DURATION, 2.0), var.lead_in(0.0, 0.2)),
                 var.DYNAMIC_DRAWS)),
    Scenario(NAME, "sliding wheel", duration=2.0, kind=ScenarioKind.MEASUREMENT,
             evaluate=_on_model(sliding.sliding_wheel),
             description="torque ramp to the slip onset, then five torque pulses 5-23 % "
                         "above the traction limit, 0.2-0.6 s long: sliding and re-grip "
                         "against the Coulomb closed form, worst over the pulses"),
)

#: Driven by ``(v, ω)``: rolling speed and the rate of the steering hinge, which is the
#: disc's heading (no steering joint relative to a chassis).
COMMAND = RateCommand(("v", "omega"), ("m/s", "rad/s"), wheels=("wheel",),
                      kinematics=lambda p: DiscKinematics(params_or_default(p, DiscParams)))

SPEC = RobotSpec(
    name=NAME,
    description="single steerable thin disc on a vertical mount; inputs wheel rate and "
                "steering rate",
    params_type=DiscParams, build=builder.build, folder="disc", robot_file="disc.xml",
    adapters={ScenarioKind.KINEMATIC: kinematic_adapter,
              ScenarioKind.DYNAMIC: dynamic_adapter},
    judges={ScenarioKind.DYNAMIC: judge_rolling},
    targets=TARGETS, scenarios=SCENARIOS, demo_scenario="constant steering",
    render_scenario="sinusoidal steering", picture=Picture(joint_angles={"steer": 0.35}),
    clips=(Clip(duration=5.0),), scene_extras=builder.floor_pair, command=COMMAND,
    learning=Learning("Disc"),
)
