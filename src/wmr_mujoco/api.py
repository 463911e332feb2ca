"""Simulate, predict, compare: the public entry points, on any registered robot.

* :func:`simulate` drives the MuJoCo model with the inputs (through contact only) and
  returns its trajectory at every physics step;
* :func:`predict` integrates the robot's analytic model (RK4 on the same time grid, from
  the same settled start) with the same inputs;
* :func:`compare` does both in one run and judges the difference with the robot's
  targets, exactly as ``wmr validate`` does.

All three go through the validation runner (:func:`~wmr_mujoco.validation.runner.prepare`,
:func:`~wmr_mujoco.sim.engine.simulate`, :func:`~wmr_mujoco.validation.runner.measure`):
there is one engine, one adapter per robot and kind, one set of metrics. Inputs are the
lecture's, per robot and kind (``wmr scenarios ROBOT`` and ``docs/analytical.md``): for
omni3 kinematic inputs, the body twist ``(u, v, r)`` in m/s, m/s, rad/s; with
``world_frame=True`` the world rates ``(Ẋ, Ẏ, ψ̇)``.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import mujoco
import numpy as np
from dm_control import mjcf

from wmr_mujoco.models import loading
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots import get_spec
from wmr_mujoco.sim.engine import STATE_SPEC, Engine
from wmr_mujoco.sim.engine import simulate as run_engine
from wmr_mujoco.validation.metrics import Row, Trace
from wmr_mujoco.validation.runner import Job, Prepared, jobs, measure, prepare
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.signals import const
from wmr_mujoco.validation.spec import RobotSpec

#: An input channel: a constant, or a function of the time after the settle (s).
Input = float | Callable[[float], float]


@dataclass(frozen=True)
class Trajectory:
    """States at every physics step, the start included.

    Attributes:
        time: ``(N + 1,)`` seconds after the settle.
        states: ``(N + 1, n)`` the analytic state's quantities (``state_names``).
        inputs: ``(N, m)`` the input held over each step.
        state_names: e.g. ``("x", "y", "heading")``.
        state_units: e.g. ``("m", "m", "rad")``.
    """

    time: np.ndarray
    states: np.ndarray
    inputs: np.ndarray
    state_names: tuple[str, ...]
    state_units: tuple[str, ...]

    def __getitem__(self, name: str) -> np.ndarray:
        """One state component over time, by name.

        Raises:
            KeyError: no such component; the message lists them.
        """
        if name not in self.state_names:
            raise KeyError(f"{name!r}; the components are {', '.join(self.state_names)}")
        return self.states[:, self.state_names.index(name)]

    @property
    def pose(self) -> np.ndarray:
        """``(N + 1, 3)`` planar pose ``(x, y, heading)``.

        Raises:
            ValueError: the state is not a pose (a dynamic state of velocities).
        """
        if self.state_names[:3] != ("x", "y", "heading"):
            raise ValueError(f"the state {self.state_names} is not a planar pose")
        return self.states[:, :3]


@dataclass(frozen=True)
class Comparison:
    """Physics and analytic model from one run, and the judged metrics.

    Attributes:
        sim: the MuJoCo trajectory.
        model: the analytic model's trajectory, same grid and start.
        metrics: the robot's judged (and informative) metrics, as ``wmr validate``.
    """

    sim: Trajectory
    model: Trajectory
    metrics: list[Row] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        """Every judged metric within its target."""
        return all(r.passed is not False for r in self.metrics)

    def metric(self, name: str, unit: str | None = None) -> float:
        """A metric's value by name (and unit).

        Raises:
            ValueError: no such metric (and unit); the message lists the valid ones.
        """
        for r in self.metrics:
            if r.metric == name and (unit is None or r.unit == unit):
                return r.value
        shown = repr(name) if unit is None else f"{name!r} [{unit}]"
        raise ValueError(f"metric {shown} not found; valid metrics: "
                         f"{', '.join(sorted({f'{r.metric} [{r.unit}]' for r in self.metrics}))}")


def _seconds(name: str, value: object, zero_ok: bool) -> float:
    """``value`` as seconds: a finite real number, > 0 (``>= 0`` with ``zero_ok``).

    Raises:
        ValueError: anything else (None, a string, a list, NaN, out of range), named with
            the valid range.
    """
    valid = "[0, inf)" if zero_ok else "(0, inf)"
    if (isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating))
            or not np.isfinite(value) or value < 0 or (value == 0 and not zero_ok)):
        raise ValueError(f"{name} = {value!r}; must be a finite real number of seconds "
                         f"in {valid}")
    return float(value)


def _scenario(robot: str, inputs: Sequence[Input], duration: float, kind: ScenarioKind | str,
              settle: float, world_frame: bool) -> Scenario:
    if isinstance(inputs, (str, bytes)) or not isinstance(inputs, Sequence):
        raise ValueError(f"inputs = {inputs!r}; give one number or function of time per "
                         "input channel")
    signals = []
    for i, u in enumerate(inputs):
        if isinstance(u, (int, float)) and not isinstance(u, bool) and np.isfinite(u):
            signals.append(const(float(u)))
        elif callable(u):
            signals.append(u)
        else:
            raise ValueError(f"inputs[{i}] = {u!r}; give a finite number or a function of "
                             "time (s) returning one")
    return Scenario(robot, "user inputs", tuple(signals),  # type: ignore[arg-type]
                    _seconds("duration", duration, zero_ok=False), kind, world_frame,
                    _seconds("settle", settle, zero_ok=True))


def _prepare(robot: str, inputs: Sequence[Input], duration: float, params: RobotParams | None,
             kind: ScenarioKind | str, settle: float, world_frame: bool) -> Prepared:
    return prepare(get_spec(robot), _scenario(robot, inputs, duration, kind, settle,
                                              world_frame), params)


def _model_trajectory(prep: Prepared) -> Trajectory:
    dt = prep.model.opt.timestep
    n = len(prep.analytic)
    return Trajectory(np.arange(n) * dt, prep.analytic, prep.inputs,
                      tuple(prep.adapter.state_names), tuple(prep.adapter.state_units))


def _sim_trajectory(prep: Prepared, states: np.ndarray) -> Trajectory:
    """The adapter's quantities read from every stored physics state."""
    model, data, adapter = prep.model, mujoco.MjData(prep.model), prep.adapter
    out = []
    for state in states:
        mujoco.mj_setState(model, data, state, STATE_SPEC)
        mujoco.mj_forward(model, data)
        out.append(adapter.sim_state(model, data))
    dt = model.opt.timestep
    return Trajectory(np.arange(len(states)) * dt, np.asarray(out), prep.inputs,
                      tuple(adapter.state_names), tuple(adapter.state_units))


def simulate(robot: str, inputs: Sequence[Input], duration: float,
             params: RobotParams | None = None, *, kind: ScenarioKind | str = "kinematic",
             settle: float = 0.5, world_frame: bool = False) -> Trajectory:
    """Drive ``robot`` in MuJoCo with ``inputs`` for ``duration`` seconds.

    The robot first settles at rest for ``settle`` seconds; then at every step the input
    ``u(t)`` becomes actuator controls (the robot's adapter) and only contact moves it.

    Args:
        robot: a registered robot (``wmr list``).
        inputs: one constant or function of time per input channel (the module docstring).
        duration: seconds after the settle.
        params: the robot's parameter dataclass (None: the checked-in model).
        kind: ``"kinematic"`` (rates) or ``"dynamic"`` (torques).
        settle: seconds at rest first.
        world_frame: the inputs are world rates (robots whose adapter takes them).

    Returns:
        The physics' trajectory at every step.

    Raises:
        ValueError: unknown robot or kind, bad inputs, duration or params.
        SimulationDivergedError: the run diverged.
    """
    prep = _prepare(robot, inputs, duration, params, kind, settle, world_frame)
    states = run_engine(prep.model, prep.data, prep.controls, Engine.ROLLOUT)
    return _sim_trajectory(prep, states)


def predict(robot: str, inputs: Sequence[Input], duration: float,
            params: RobotParams | None = None, *, kind: ScenarioKind | str = "kinematic",
            settle: float = 0.5, world_frame: bool = False) -> Trajectory:
    """The analytic model's trajectory for the same arguments as :func:`simulate`.

    It starts from the state the physics settles into (read by the robot's adapter) and
    is integrated by RK4 on MuJoCo's time grid, the input held over each step.

    Raises:
        ValueError: as :func:`simulate`.
    """
    return _model_trajectory(_prepare(robot, inputs, duration, params, kind, settle,
                                      world_frame))


def compare(robot: str, inputs: Sequence[Input], duration: float,
            params: RobotParams | None = None, *, kind: ScenarioKind | str = "kinematic",
            settle: float = 0.5, world_frame: bool = False) -> Comparison:
    """:func:`simulate` and :func:`predict` in one run, judged as ``wmr validate`` judges.

    Raises:
        ValueError: as :func:`simulate`.
        SimulationDivergedError: the run diverged.
    """
    prep = _prepare(robot, inputs, duration, params, kind, settle, world_frame)
    states = run_engine(prep.model, prep.data, prep.controls, Engine.ROLLOUT)
    rows = measure(prep, states, Trace())
    return Comparison(_sim_trajectory(prep, states), _model_trajectory(prep), rows)


def _spec(robot: str | RobotSpec) -> RobotSpec:
    """The registry entry of a robot name; a spec as it is.

    Raises:
        ValueError: unknown robot name (the message lists the valid ones).
    """
    return robot if isinstance(robot, RobotSpec) else get_spec(robot)


def load(robot: str | RobotSpec, params: RobotParams | None = None) -> mujoco.MjModel:
    """The compiled scene (robot, floor, light) of a registered robot or a spec.

    Args:
        robot: a name from :data:`wmr_mujoco.robots.ROBOTS`, or a ``RobotSpec``.
        params: None to load the checked-in ``scene.xml`` (a robot without files is built
            from its defaults); otherwise an instance of the robot's parameter dataclass.

    Raises:
        ValueError: unknown robot name (the message lists the valid ones) or wrong
            parameter type.
        FileNotFoundError: the scene file is missing (the message names the path).
    """
    return loading.load(_spec(robot), params)


def build_scene(robot: str | RobotSpec, params: RobotParams | None = None
                ) -> mjcf.RootElement:
    """The robot built from ``params`` (defaults if None) with floor and light, unbuilt.

    Raises:
        ValueError: unknown robot name, a robot without a builder, or wrong ``params``.
    """
    return loading.build_scene(_spec(robot), params)


def validation_jobs(robots: Sequence[str] | None = None,
                    names: Sequence[str] | None = None) -> list[Job]:
    """The registered scenarios of ``robots`` (all if None), each with its robot.

    Args:
        robots: registry names, in the order wanted (None: every robot, registry order).
        names: keep only the scenarios of these names (None: all).

    Raises:
        ValueError: an unknown robot, one without scenarios, or a name none of the chosen
            robots has; the message lists the valid ones.
    """
    from wmr_mujoco.robots import ROBOTS

    if robots is None:
        specs = list(ROBOTS.values())
    else:
        have = [name for name, spec in ROBOTS.items() if spec.scenarios]
        specs = [get_spec(r) for r in robots]
        for spec in specs:
            if not spec.scenarios:
                raise ValueError(f"no validation scenarios for robot {spec.name!r}; robots "
                                 f"with scenarios: {', '.join(have)}")
    work = jobs(specs)
    if names:
        valid = [s.name for _, s in work]
        unknown = [n for n in names if n not in valid]
        if unknown:
            where = ", ".join(robots or ()) or "any robot"
            raise ValueError(f"no scenario {unknown[0]!r} for {where}; valid: "
                             f"{', '.join(repr(n) for n in dict.fromkeys(valid))}")
        work = [(spec, s) for spec, s in work if s.name in names]
    return work
