"""Wheels on the floor under step commands and random stepped inputs, for any robot.

Two input families, both through the robot's own kinematic adapter (its lecture inputs,
e.g. the body twist ``(u, v, r)`` of omni3 and mecanum4, become its actuator controls):

* **steps from rest**: the robot settled for ``SETTLE`` s, then a step to a draw of
  :func:`~wmr_mujoco.sim.stepped_inputs.step_draws`; read over the first
  :data:`STEP_WINDOW` s, where a step's start-up slides the wheels;
* **random steps**: a draw of :func:`~wmr_mujoco.sim.stepped_inputs.random_steps`, a new
  input every control period, over :data:`RANDOM_DURATION` s.

The command range is the robot's own: per input, the largest magnitude its kinematic
validation scenarios command (sampled every 10 ms). Each step is read by
:class:`~wmr_mujoco.sim.floor_contact.WheelMap` (off-floor wheels, penetration).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.models.actuation import set_actuation_mode
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots import get_spec
from wmr_mujoco.robots.spec import RobotSpec
from wmr_mujoco.sim.floor_contact import FloorReading, FloorRecorder, WheelMap
from wmr_mujoco.sim.stepped_inputs import CONTROL_PERIOD, random_steps, step_draws
from wmr_mujoco.sim.stepping import check_healthy
from wmr_mujoco.validation import floor_family
from wmr_mujoco.validation.adapters import Adapter
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind

#: Seconds at rest before the inputs start (as the validation scenarios).
SETTLE = 0.5
#: Seconds after a step from rest that are read: its start-up.
STEP_WINDOW = 0.1
#: Seconds of a random stepped run.
RANDOM_DURATION = 10.0

#: ``setup(model)``: changes the loaded model before it settles (e.g. its timestep).
Setup = Callable[[mujoco.MjModel], None]


def _kinematic(spec: RobotSpec) -> Scenario:
    for s in spec.scenarios:
        if s.kind is ScenarioKind.KINEMATIC and not s.world_frame:
            return s
    raise ValueError(f"robot {spec.name!r} has no body-frame kinematic scenario to drive it")


def command_bounds(robot: str) -> np.ndarray:
    """Per lecture input, the largest magnitude a user commands.

    See :func:`wmr_mujoco.validation.floor_family.command_bounds`.

    Raises:
        ValueError: an unknown robot, or one without a body-frame kinematic scenario.
    """
    return floor_family.command_bounds(get_spec(robot))


@dataclass
class Settled:
    """A robot loaded, in its adapter's actuation mode, settled at rest.

    Attributes:
        model, data: the physics (``data`` is reset to ``state`` before every run).
        adapter: its kinematic adapter.
        wheels: its wheel map.
        state: the settled state with warm start and controls (``mjSTATE_INTEGRATION``).
    """

    model: mujoco.MjModel
    data: mujoco.MjData
    adapter: Adapter
    wheels: WheelMap
    state: np.ndarray


STATE = mujoco.mjtState.mjSTATE_INTEGRATION


def settled(robot: str, params: RobotParams | None = None,
            setup: Setup | None = None) -> Settled:
    """Load ``robot``, apply ``setup``, and settle it at rest for :data:`SETTLE` s.

    Raises:
        SimulationDivergedError: the settle diverged.
    """
    from wmr_mujoco import load

    spec = get_spec(robot)
    model = load(robot, params)
    if setup is not None:
        setup(model)
    scenario = _kinematic(spec)
    adapter = spec.adapters[ScenarioKind.KINEMATIC](scenario, model, params)
    if adapter.mode is not None:
        set_actuation_mode(model, adapter.mode)
    data = mujoco.MjData(model)
    for _ in range(round(SETTLE / model.opt.timestep)):
        mujoco.mj_step(model, data)
    check_healthy(model, data)
    state = np.empty(mujoco.mj_stateSize(model, STATE))
    mujoco.mj_getState(model, data, state, STATE)
    return Settled(model, data, adapter, WheelMap.of(model), state)


def drive(run: Settled, inputs: np.ndarray, period: float) -> FloorReading:
    """From the settled state, hold each row of ``inputs`` for ``period`` s; read each step.

    The analytic state that an adapter's controls may depend on (a steering angle) is
    read from the physics at each period's start, as a controller would read it.

    Raises:
        SimulationDivergedError: the physics diverged.
    """
    m, d, ad = run.model, run.data, run.adapter
    mujoco.mj_setState(m, d, run.state, STATE)
    mujoco.mj_forward(m, d)
    dt = m.opt.timestep
    per = max(1, round(period / dt))
    rec = FloorRecorder(run.wheels, per * len(inputs))
    for u in np.asarray(inputs, float):
        d.ctrl[:] = ad.controls(u, np.asarray(ad.sim_state(m, d), float))
        for _ in range(per):
            mujoco.mj_step(m, d)
            rec.record(d)
        check_healthy(m, d)
    return rec.reading()


def _merge(readings: list[FloorReading]) -> FloorReading:
    return FloorReading(readings[0].wheels,
                        np.concatenate([r.off_floor for r in readings]),
                        np.concatenate([r.depth for r in readings]))


@dataclass(frozen=True)
class FloorFigures:
    """A robot's floor-contact figures over both families.

    Attributes:
        robot: registry name.
        wheels: wheel names found (:class:`WheelMap`).
        steps: reading of every step draw's first :data:`STEP_WINDOW` s, concatenated.
        step_worst: largest off-floor share of one step draw, in [0, 1].
        random: readings of the random stepped runs, one per seed.
    """

    robot: str
    wheels: tuple[str, ...]
    steps: FloorReading
    step_worst: float
    random: tuple[FloorReading, ...]

    @property
    def random_worst(self) -> float:
        """Largest off-floor share of one random run, in [0, 1]."""
        return max(r.off_floor_share for r in self.random)

    @property
    def max_depth(self) -> float:
        """Deepest penetration over every run, m."""
        return max([self.steps.max_depth, *(r.max_depth for r in self.random)])


def floor_figures(robot: str, step_count: int, random_seeds: tuple[int, ...],
                  seed: int = 0, params: RobotParams | None = None,
                  setup: Setup | None = None,
                  random_duration: float = RANDOM_DURATION) -> FloorFigures:
    """Both families for ``robot``: steps from rest and random stepped runs.

    ``step_count`` steps (seeded ``seed``) and one random stepped run per seed of
    ``random_seeds``.

    Raises:
        ValueError: an unknown robot, a robot without kinematic scenarios, or bad counts.
    """
    if not random_seeds:
        raise ValueError("random_seeds is empty; give at least one seed")
    bounds = command_bounds(robot)
    run = settled(robot, params, setup)
    steps = [drive(run, u[None, :], STEP_WINDOW) for u in step_draws(bounds, step_count, seed)]
    runs = tuple(drive(run, random_steps(bounds, random_duration, s), CONTROL_PERIOD)
                 for s in random_seeds)
    return FloorFigures(robot, steps[0].wheels, _merge(steps),
                        max(r.off_floor_share for r in steps), runs)
