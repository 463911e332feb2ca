"""The Whipple benchmark bicycle (Meijaard, Papadopoulos, Ruina & Schwab 2007).

A riderless bicycle on knife-edge wheels, uncontrolled, measured against the benchmark's
linearised equations (:mod:`wmr_mujoco.robots.whipple.analytic`). Its scenarios are all
measurements in the physics:

* ``critical speeds``: weave and capsize speeds from the physics (:mod:`.eigen`);
* ``eigenvalues vs speed``: weave, capsize and castering at 1-10 m/s, with the
  benchmark's eigenvalue-versus-speed figure (:mod:`.eigen`);
* ``push at v m/s``: self-stability after a sideways push (:mod:`.stability`); each
  films its free run from its start state (:func:`~wmr_mujoco.validation.scenarios.free_run`),
  so ``wmr render whipple --scenario "push at 5 m/s"`` films the run that is measured.
"""

from __future__ import annotations

from wmr_mujoco.robots.learning import Bands, Learning
from wmr_mujoco.robots.spec import Clip, Picture, RobotSpec
from wmr_mujoco.robots.whipple import builder, eigen, lean, stability
from wmr_mujoco.robots.whipple.params import WhippleParams
from wmr_mujoco.robots.whipple.rolling import NAME, compile_model, pushed, readings
from wmr_mujoco.validation.command import Balance, TorqueCommand
from wmr_mujoco.validation.family import Family, Vary
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind, free_run
from wmr_mujoco.validation.variations import DYNAMIC_DRAWS


def push_name(speed: float) -> str:
    """Name of the push scenario at ``speed``."""
    return f"push at {speed:g} m/s"


#: What a user would vary in a push: its strength, the lean rate it gives, ±20 %.
PUSH_FAMILY = Family((Vary(stability.PUSH, 0.8 * stability.PUSH_LEAN_RATE,
                           1.2 * stability.PUSH_LEAN_RATE, "rad/s"),), DYNAMIC_DRAWS)


def _push(speed: float, what: str) -> Scenario:
    evaluate, start = stability.push_scenario_parts(speed)
    return Scenario(NAME, push_name(speed), duration=stability.PUSH_DURATION,
                    kind=ScenarioKind.MEASUREMENT, settle=0.0, evaluate=evaluate,
                    film=free_run(start, compile_model),
                    description=f"sideways push at {speed:g} m/s: {what}",
                    family=PUSH_FAMILY)


SCENARIOS = (
    Scenario(NAME, "critical speeds", kind=ScenarioKind.MEASUREMENT, settle=0.0,
             evaluate=eigen.evaluate_critical_speeds,
             description="weave and capsize speeds from the step map's eigenvalues"),
    Scenario(NAME, "eigenvalues vs speed", kind=ScenarioKind.MEASUREMENT, settle=0.0,
             evaluate=eigen.evaluate_eigenvalues,
             description="weave, capsize, castering at 1-10 m/s against the benchmark"),
    *(_push(v, "self-stable, the lean decays") for v in stability.STABLE_SPEEDS),
    _push(stability.UNSTABLE_SPEED, "below the weave speed, it falls"),
)

#: Driven by its own actuators, the rear-wheel and steer torques. It cannot stand still:
#: a reset starts it rolling upright at the ``rolling`` keyframe's speed (inside the
#: self-stable range), with no settling. Its balancing data (pushed start, LQR, linear
#: model: :mod:`.lean`) give it the upright scenarios at 3 and 2 m/s
#: (:mod:`wmr_mujoco.loop.tasks.families`).
COMMAND = TorqueCommand(("rear_torque", "steer_torque"), ("N·m", "N·m"),
                        wheels=("rear_wheel", "front_wheel"), steers=("steer",),
                        settle=0.0, keyframe="rolling", extras=readings,
                        actuators=("rear_torque", "steer_torque"),
                        balance=Balance(pushed, lean.law, lean.SPEEDS, lean.PUSH,
                                        lean.PUSH_RANGE, lean.PERIOD, stability.FALLEN,
                                        linear=lean.linear_leans))

SPEC = RobotSpec(
    name=NAME,
    description="Whipple benchmark bicycle (Meijaard et al. 2007): knife-edge wheels, "
                "steer axis, no control; self-stable between its weave and capsize speeds",
    params_type=WhippleParams, build=builder.build, folder=NAME, robot_file="whipple.xml",
    scenarios=SCENARIOS,
    render_scenario=push_name(5.0),
    picture=Picture(keyframe="upright", joint_angles={"steer": 0.3}),
    clips=(Clip(duration=8.0), Clip(push_name(3.0), "whipple_fall.gif", 3.0)),
    command=COMMAND,
    # Knife-edge wheels (no radius band); a balance task at 100 Hz.
    learning=Learning("Whipple", tasks=("StayUpright",), control_period=0.01,
                      bands=Bands(friction=(0.7, 1.3), mass=(0.9, 1.1),
                                  wheel_radius=None, servo_gain=(0.9, 1.1))),
)
