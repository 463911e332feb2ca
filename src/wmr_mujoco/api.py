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

Every argument is checked before anything is simulated: a run whose trajectory would
not fit :data:`~wmr_mujoco.run_limits.MAX_MEMORY` (or ``max_memory``, or ``WMR_MAX_MEMORY``) is
refused, and inputs that ask an actuator for more than its ``ctrlrange`` are simulated
with an :class:`~wmr_mujoco.run_limits.InputClippedWarning` (MuJoCo clips the control,
the analytic model does not); see :mod:`wmr_mujoco.run_limits`.
"""

from __future__ import annotations

import numbers
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import mujoco
import numpy as np

from wmr_mujoco.models import loading
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots import get_spec
from wmr_mujoco.run_limits import (
    MAX_MEMORY,
    InputClippedWarning,
    check_frame,
    check_steps,
    warn_clipped,
)
from wmr_mujoco.sim.engine import STATE_SPEC, Engine
from wmr_mujoco.sim.engine import simulate as run_engine
from wmr_mujoco.validation.metrics import Row, Trace
from wmr_mujoco.validation.runner import (
    Prepared,
    check_runnable,
    make_adapter,
    measure,
    prepare,
)
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.signals import const

#: An input channel: a constant, or a function of the time after the settle (s).
Input = float | Callable[[float], float]

class NamedStates:
    """Named access to ``states`` whose last axis is ``state_names`` (one run or a batch)."""

    states: np.ndarray
    state_names: tuple[str, ...]

    def __getitem__(self, name: str) -> np.ndarray:
        """One state component over time (member first in a batch), by name.

        Raises:
            KeyError: no such component; the message lists them.
        """
        if name not in self.state_names:
            raise KeyError(f"{name!r}; the components are {', '.join(self.state_names)}")
        return self.states[..., self.state_names.index(name)]

    @property
    def pose(self) -> np.ndarray:
        """``(..., N + 1, 3)`` planar pose ``(x, y, heading)``.

        Raises:
            ValueError: the state is not a pose (a dynamic state of velocities).
        """
        if self.state_names[:3] != ("x", "y", "heading"):
            raise ValueError(f"the state {self.state_names} is not a planar pose")
        return self.states[..., :3]


@dataclass(frozen=True)
class Trajectory(NamedStates):
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


@dataclass(frozen=True)
class _Channel:
    """A user's input function, its failures named by channel and time."""

    index: int
    function: Callable[[float], float]

    def __call__(self, t: float) -> float:
        """``function(t)`` as a float.

        Raises:
            ValueError: the function raised, or returned no finite real number.
        """
        try:
            value = self.function(t)
        except Exception as err:
            raise ValueError(f"inputs[{self.index}] raised {type(err).__name__}: {err} at "
                             f"t = {t:g} s") from err
        if not _is_number(value):
            raise ValueError(f"inputs[{self.index}]({t:g}) returned {value!r}; an input "
                             "function must return a finite real number")
        return float(value)


def _is_number(value: object) -> bool:
    """A finite real number (a NumPy scalar or 0-d array too), not a bool."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value.item()
    return (isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_))
            and bool(np.isfinite(value)))


def _scenario(robot: str, inputs: Sequence[Input], duration: float, kind: ScenarioKind | str,
              settle: float, world_frame: bool) -> Scenario:
    if isinstance(inputs, np.ndarray) and inputs.ndim == 1:
        inputs = list(inputs)
    if isinstance(inputs, (str, bytes)) or not isinstance(inputs, Sequence):
        raise ValueError(f"inputs = {inputs!r}; give one number or function of time per "
                         "input channel (a list, a tuple or a 1-D NumPy array)")
    signals = []
    for i, u in enumerate(inputs):
        if _is_number(u):
            signals.append(const(float(u)))  # type: ignore[arg-type]
        elif callable(u):
            signals.append(_Channel(i, u))
            signals[-1](0.0)  # a function that fails fails now, before any work
        else:
            raise ValueError(f"inputs[{i}] = {u!r}; give a finite number or a function of "
                             "time (s) returning one")
    return Scenario(robot, "user inputs", tuple(signals),  # type: ignore[arg-type]
                    _seconds("duration", duration, zero_ok=False), kind, world_frame,
                    _seconds("settle", settle, zero_ok=True))


def _prepare(robot: str, inputs: Sequence[Input], duration: float, params: RobotParams | None,
             kind: ScenarioKind | str, settle: float, world_frame: bool,
             max_memory: float | None = None, physics: bool = True) -> Prepared:
    """Check everything, then load, settle and schedule (warning of clipped inputs)."""
    spec = get_spec(robot)
    s = _scenario(spec.name, inputs, duration, kind, settle, world_frame)
    check_runnable(spec, s)
    model = loading.load(spec, params)
    adapter = make_adapter(spec, s, model, params)
    check_frame(s, adapter)
    check_steps(s, model, adapter, max_memory)
    prep = prepare(spec, s, params, model=model)
    if physics:
        warn_clipped(prep)
    return prep


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
             settle: float = 0.5, world_frame: bool = False,
             max_memory: float | None = None) -> Trajectory:
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
        max_memory: the largest trajectory allowed, bytes (None: ``WMR_MAX_MEMORY`` if
            set, else :data:`~wmr_mujoco.run_limits.MAX_MEMORY`).

    Returns:
        The physics' trajectory at every step.

    Raises:
        ValueError: unknown robot or kind; bad inputs (an input function that raises is
            named with its channel and time), params, or duration (shorter than one
            timestep, or a trajectory over the memory cap); ``world_frame`` for a robot
            whose inputs are never world rates.
        SimulationDivergedError: the run diverged.

    Warns:
        InputClippedWarning: an input asks an actuator for more than its ``ctrlrange``.
    """
    prep = _prepare(robot, inputs, duration, params, kind, settle, world_frame, max_memory)
    states = run_engine(prep.model, prep.data, prep.controls, Engine.ROLLOUT)
    return _sim_trajectory(prep, states)


def predict(robot: str, inputs: Sequence[Input], duration: float,
            params: RobotParams | None = None, *, kind: ScenarioKind | str = "kinematic",
            settle: float = 0.5, world_frame: bool = False,
            max_memory: float | None = None) -> Trajectory:
    """The analytic model's trajectory for the same arguments as :func:`simulate`.

    It starts from the state the physics settles into (read by the robot's adapter) and
    is integrated by RK4 on MuJoCo's time grid, the input held over each step.

    Raises:
        ValueError: as :func:`simulate`.
    """
    return _model_trajectory(_prepare(robot, inputs, duration, params, kind, settle,
                                      world_frame, max_memory, physics=False))


def compare(robot: str, inputs: Sequence[Input], duration: float,
            params: RobotParams | None = None, *, kind: ScenarioKind | str = "kinematic",
            settle: float = 0.5, world_frame: bool = False,
            max_memory: float | None = None) -> Comparison:
    """:func:`simulate` and :func:`predict` in one run, judged as ``wmr validate`` judges.

    Raises:
        ValueError: as :func:`simulate`.
        SimulationDivergedError: the run diverged.

    Warns:
        InputClippedWarning: as :func:`simulate`.
    """
    prep = _prepare(robot, inputs, duration, params, kind, settle, world_frame, max_memory)
    states = run_engine(prep.model, prep.data, prep.controls, Engine.ROLLOUT)
    rows = measure(prep, states, Trace())
    return Comparison(_sim_trajectory(prep, states), _model_trajectory(prep), rows)


__all__ = [
    "MAX_MEMORY",
    "Comparison",
    "Input",
    "InputClippedWarning",
    "Trajectory",
    "compare",
    "predict",
    "simulate",
]
