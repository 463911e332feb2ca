"""The "random steps" family: the wheels stay on the floor under stepped commands.

A policy or controller holds its command for one control period and then steps to the
next (:mod:`wmr_mujoco.sim.stepped_inputs`). This measurement scenario drives any robot
with a kinematic adapter that way, in the robot's own command space: its adapter's
lecture inputs (the body twist ``(u, v, r)`` of omni3 and mecanum4, ``(v, ω)`` of a
differential drive, ...), bounded per input by :func:`command_bounds`. One member is one
run from rest (after the scenario's settle):

* the first control period is a step from rest to a random direction on the surface of
  the command box (:func:`~wmr_mujoco.sim.stepped_inputs.step_draws`: as large as the
  range allows in that direction, the step that slides the wheels most);
* every later period a new input uniform in the box
  (:func:`~wmr_mujoco.sim.stepped_inputs.random_steps`), a step of random size and
  direction every :data:`~wmr_mujoco.sim.stepped_inputs.CONTROL_PERIOD` s, over
  :data:`DURATION` s in all.

A member draws the wheels' start angle (``wheel phase``, added to every wheel joint of
``spec.command.wheels`` before the settle: a full turn covers every roller pitch) and the
seed of its schedule (``inputs``, a fraction of 2³² turned into an integer seed).

Each step's contacts are read by per-wheel contact sensors
(:func:`~wmr_mujoco.sim.floor_contact.add_floor_sensors`) that ``mujoco.rollout``
records, and judged against the requirements of issue 24 § 3:

* share of wheel samples without floor contact in the first :data:`STEP_WINDOW` s after
  the step from rest ≤ 1 %;
* the same share over the whole run ≤ 0.1 %;
* the deepest penetration of a wheel into the floor ≤ 0.5 mm.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import mujoco
import numpy as np

from wmr_mujoco.models.actuation import set_actuation_mode
from wmr_mujoco.models.builders.common import to_xml
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.sim.floor_contact import (
    FloorReading,
    WheelMap,
    add_floor_sensors,
    sensor_columns,
    sensor_reading,
)
from wmr_mujoco.sim.stepped_inputs import CONTROL_PERIOD, random_steps, step_draws
from wmr_mujoco.sim.stepping import SimulationDivergedError, check_healthy
from wmr_mujoco.validation.family import Family, Vary
from wmr_mujoco.validation.scenarios import (
    Evaluate,
    MeasurementResult,
    Scenario,
    ScenarioKind,
)
from wmr_mujoco.validation.spec import RobotSpec
from wmr_mujoco.validation.targets import Metric, Target
from wmr_mujoco.validation.traces import Series

#: The scenario's name in every robot's registry entry.
NAME = "random steps"
#: Seconds of a run after the settle.
DURATION = 10.0
#: Seconds after the step from rest that are judged for its start-up.
STEP_WINDOW = CONTROL_PERIOD
#: Its judged metrics' names (a robot's entry may declare one open, ``RobotSpec.open_targets``).
AFTER_STEP = f"wheel samples off the floor, first {STEP_WINDOW:g} s after the step from rest"
OVER_RUN = f"wheel samples off the floor, {DURATION:g} s of random steps"
DEPTH = "deepest wheel penetration into the floor"
#: Members judged per seed (issue 24: at least 20 for a dynamic family).
DRAWS = 20
#: Varied: radians added to every wheel joint's start angle (a full turn).
WHEEL_PHASE = "wheel phase"
#: Varied: the schedule's seed as a fraction of 2³².
INPUTS = "inputs"
#: Sampling step of the kinematic scenarios' inputs when their range is read, s.
RANGE_SAMPLE = 0.01

_SOURCE = "issue 24 § 3 (wheels stay on the floor under step commands)"
STEP_TARGET = Target.requirement(1.0, _SOURCE)
RUN_TARGET = Target.requirement(0.1, _SOURCE)
DEPTH_TARGET = Target.requirement(0.5, _SOURCE)


def body_frame_scenario(spec: RobotSpec) -> Scenario | None:
    """The robot's first body-frame kinematic scenario (None: it has none)."""
    return next((s for s in spec.scenarios
                 if s.kind is ScenarioKind.KINEMATIC and not s.world_frame), None)


def applies(spec: RobotSpec) -> bool:
    """Whether the family can drive ``spec``.

    It needs a kinematic adapter, a body-frame kinematic scenario, a command map (its
    wheels) and a builder.
    """
    return (ScenarioKind.KINEMATIC in spec.adapters and body_frame_scenario(spec) is not None
            and spec.command is not None and spec.build is not None)


def command_bounds(spec: RobotSpec) -> np.ndarray:
    """Per lecture input, the largest magnitude a user commands.

    The robot's :attr:`RobotSpec.command_range` where it gives one, else the largest its
    kinematic scenarios command (sampled every :data:`RANGE_SAMPLE` s; world-frame
    scenarios count too: their rates have the body rates' sizes).

    Raises:
        ValueError: the robot has no body-frame kinematic scenario.
    """
    if body_frame_scenario(spec) is None:
        raise ValueError(f"robot {spec.name!r} has no body-frame kinematic scenario to "
                         "drive it")
    if spec.command_range is not None:
        return np.asarray(spec.command_range, float)
    got = _BOUNDS.get(id(spec))
    if got is None or got[0] is not spec:  # sampled once per spec (a family's members share it)
        scenarios = [s for s in spec.scenarios if s.kind is ScenarioKind.KINEMATIC]
        peak = np.zeros(len(scenarios[0].inputs))
        for s in scenarios:
            for t in np.arange(0.0, s.duration + RANGE_SAMPLE / 2, RANGE_SAMPLE):
                peak = np.maximum(peak, np.abs(s.input_at(float(t))))
        if len(_BOUNDS) >= 16:
            _BOUNDS.pop(next(iter(_BOUNDS)))
        got = _BOUNDS[id(spec)] = (spec, peak)
    return got[1].copy()


#: :func:`command_bounds` sampled from the scenarios, per spec (kept with its spec, so that
#: an id reused by a later spec is not mistaken for it; a spec is frozen).
_BOUNDS: dict[int, tuple[RobotSpec, np.ndarray]] = {}


def family() -> Family:
    """Wheel phase over a full turn and the schedule's seed; :data:`DRAWS` draws."""
    return Family(vary=(Vary(WHEEL_PHASE, 0.0, 2.0 * math.pi, "rad"),
                        Vary(INPUTS, 0.0, 1.0)), draws=DRAWS)


def scenario(robot: str, evaluate: Evaluate) -> Scenario:
    """The family's scenario for ``robot``, measured by ``evaluate``."""
    return Scenario(robot, NAME, duration=DURATION, kind=ScenarioKind.MEASUREMENT,
                    evaluate=evaluate, family=family(),
                    description=f"seeded random stepped commands (a step every "
                                f"{CONTROL_PERIOD:g} s, the first from rest) over "
                                f"{DURATION:g} s: wheels on the floor")


def schedule(bounds: np.ndarray, seed: int, duration: float = DURATION) -> np.ndarray:
    """Inputs of each control period: a step from rest to the box's surface, then uniform.

    Raises:
        ValueError: bad bounds, or a duration shorter than one control period.
    """
    inputs = random_steps(bounds, duration, seed)
    inputs[0] = step_draws(bounds, 1, seed)[0]
    return inputs


#: Compiled sensed scenes by (robot, parameters): a family's members share one.
_SENSED: dict[tuple[str, RobotParams | None], tuple[mujoco.MjModel, WheelMap]] = {}
#: Most scenes kept (each a few MB at most).
_SENSED_MAX = 8


def _sensed(spec: RobotSpec, params: RobotParams | None) -> tuple[mujoco.MjModel, WheelMap]:
    """The robot's scene with a floor sensor per wheel, and its wheel map (cached)."""
    from wmr_mujoco.models.loading import build_scene

    key = (spec.name, params)
    if key not in _SENSED:
        xml = to_xml(build_scene(spec, params))
        wheels = WheelMap.of(mujoco.MjModel.from_xml_string(xml))
        mjspec = mujoco.MjSpec.from_string(xml)
        add_floor_sensors(mjspec, wheels.wheels)
        if len(_SENSED) >= _SENSED_MAX:
            _SENSED.pop(next(iter(_SENSED)))
        _SENSED[key] = (mjspec.compile(), wheels)
    return _SENSED[key]


def _free_quaternion(model: mujoco.MjModel) -> int | None:
    """Index in the ``mjSTATE_FULLPHYSICS`` state of the first free joint's quaternion."""
    free = np.flatnonzero(model.jnt_type == mujoco.mjtJoint.mjJNT_FREE)
    return None if free.size == 0 else 1 + int(model.jnt_qposadr[free[0]]) + 3


def _tilt_deg(quaternions: np.ndarray) -> np.ndarray:
    """Angle between the body's z axis and the world's, deg: ``acos(1 − 2(x² + y²))``."""
    z = 1.0 - 2.0 * (quaternions[:, 1] ** 2 + quaternions[:, 2] ** 2)
    return np.degrees(np.arccos(np.clip(z, -1.0, 1.0)))


def run(spec: RobotSpec, s: Scenario, params: RobotParams | None = None,
        setup: Callable[[mujoco.MjModel], None] | None = None
        ) -> tuple[FloorReading, float]:
    """One member's run: its floor reading and the chassis' largest tilt.

    The floor reading of every step after the settle, and the largest tilt of the
    chassis (its free joint's z axis against the vertical), deg.

    ``setup(model)`` may change a copy of the model before the settle (a timestep).

    Raises:
        SimulationDivergedError: the physics diverged.
    """
    from mujoco import rollout

    cached, wheels = _sensed(spec, params)
    model = cached.__copy__()  # the actuation mode and ``setup`` change only the copy
    if setup is not None:
        setup(model)
    nominal = body_frame_scenario(spec)
    assert nominal is not None and spec.command is not None  # applies(spec)
    adapter = spec.adapters[ScenarioKind.KINEMATIC](nominal, model, params)
    if adapter.mode is not None:
        set_actuation_mode(model, adapter.mode)
    data = mujoco.MjData(model)
    phase = s.value(WHEEL_PHASE, 0.0)
    for joint in spec.command.wheels:
        data.qpos[model.jnt_qposadr[model.joint(joint).id]] += phase
    mujoco.mj_forward(model, data)
    for _ in range(round(s.settle / model.opt.timestep)):
        mujoco.mj_step(model, data)
    check_healthy(model, data)
    inputs = schedule(command_bounds(spec), int(s.value(INPUTS, 0.0) * 2**32), s.duration)
    per = max(1, round(CONTROL_PERIOD / model.opt.timestep))
    spec_state = mujoco.mjtState.mjSTATE_FULLPHYSICS
    state = np.empty(mujoco.mj_stateSize(model, spec_state))
    sensed = np.empty((len(inputs) * per, model.nsensordata))
    quat = _free_quaternion(model)
    tilt = 0.0
    for k, u in enumerate(inputs):
        ctrl = adapter.controls(u, np.asarray(adapter.sim_state(model, data), float))
        mujoco.mj_getState(model, data, state, spec_state)
        states, sensordata = rollout.rollout(
            model, data, state, np.tile(ctrl, (per, 1))[None],
            initial_warmstart=data.qacc_warmstart.copy()[None])
        if not np.all(np.isfinite(states)):
            raise SimulationDivergedError(f"{s.key}: non-finite state in control period {k}")
        sensed[k * per:(k + 1) * per] = sensordata[0]
        if quat is not None:
            tilt = max(tilt, float(_tilt_deg(states[0, :, quat:quat + 4]).max()))
        mujoco.mj_setState(model, data, states[0, -1], spec_state)
        mujoco.mj_forward(model, data)
        check_healthy(model, data)
    return sensor_reading(wheels.wheels, sensor_columns(model, wheels.wheels), sensed), tilt


def measure(spec: RobotSpec, s: Scenario, params: RobotParams | None = None
            ) -> MeasurementResult:
    """The judged metrics of one member (see the module docstring)."""
    reading, tilt = run(spec, s, params)
    dt = s.duration / len(reading.depth)
    first = max(1, round(STEP_WINDOW / dt))
    after_step = 100.0 * float(np.mean(reading.off_floor[:first]))
    whole = 100.0 * reading.off_floor_share
    t = dt * np.arange(1, len(reading.depth) + 1)
    off = 100.0 * reading.off_floor.mean(axis=1)
    return MeasurementResult(
        [Metric(AFTER_STEP, after_step, "%", STEP_TARGET),
         Metric(OVER_RUN, whole, "%", RUN_TARGET),
         Metric(DEPTH, 1e3 * reading.max_depth, "mm", DEPTH_TARGET),
         Metric("largest tilt of the chassis", tilt, "deg",
                note="reported: a robot that tips over lifts its wheels for real")],
        [Series("wheels off the floor", t, off, "s", "%")])
