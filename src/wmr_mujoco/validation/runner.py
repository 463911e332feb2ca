"""The one runner: scenarios through MuJoCo and the analytic models, measured and judged.

For each kinematic or dynamic :class:`~wmr_mujoco.validation.scenarios.Scenario` the
simulation and the analytic model advance together on MuJoCo's time grid: at step k the
input ``u(t_k)`` becomes actuator controls and is held over the step in the analytic
model's RK4 step (:func:`wmr_mujoco.analytic.integrate.rk4_step`), from the same settled
initial state. The robot's adapter, judge, probes and targets come from the
:class:`~wmr_mujoco.validation.spec.RobotSpec` the caller passes with the scenario; nothing
here looks a robot up or knows one by name. A measurement scenario's own ``evaluate``
runs instead, and its metrics are judged the same way.

One execution path: :func:`run_scenario` runs one scenario (one member of a family: the
generic variations of :mod:`wmr_mujoco.validation.variations` are applied through
``Scenario.input_at`` and ``Scenario.member``, the wheel phase before the settle in
:func:`prepare`); :func:`run_all` runs scenarios once each, and
:mod:`wmr_mujoco.validation.members` runs every member of their families and judges the
worst: a family's members share one model and are simulated in one threaded rollout
there, and ``wmr validate --jobs N`` runs the families in N processes
(:mod:`wmr_mujoco.validation.pool`).

Metrics are in :mod:`wmr_mujoco.validation.metrics` (pose tracking: worst, RMS and final
errors over the whole run; lateral slip) and in each robot's module (dynamic judges,
probes).
"""

from __future__ import annotations

import math
import traceback
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import mujoco
import numpy as np

from wmr_mujoco.analytic.integrate import rk4_step
from wmr_mujoco.models.actuation import set_actuation_mode
from wmr_mujoco.models.loading import load
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.sim.engine import STATE_SPEC, Engine, simulate
from wmr_mujoco.sim.stepping import SimulationDivergedError, check_healthy
from wmr_mujoco.validation.adapters import Adapter, AdapterFactory
from wmr_mujoco.validation.metrics import (
    RECORD_EVERY,
    Metric,
    Probe,
    Row,
    Sample,
    Trace,
    lateral_slip,
    slip_metrics,
)
from wmr_mujoco.validation.resample import restore_step, sync_kinematics
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.spec import RobotSpec
from wmr_mujoco.validation.units import announce
from wmr_mujoco.validation.variations import WHEEL_PHASE, add_wheel_phase

#: A scenario with the robot it runs on.
Job = tuple[RobotSpec, Scenario]



def jobs(specs: Sequence[RobotSpec]) -> list[Job]:
    """Every scenario of ``specs``, each with its robot, in the given order."""
    return [(spec, s) for spec in specs for s in spec.scenarios]


@dataclass
class ScenarioResult:
    """Rows and trace of one scenario (``error`` set when it diverged or raised).

    For a family: ``rows`` are the worst member's per metric, ``trace`` the worst
    member's, ``members`` every member's own result (traceless after worker processes),
    ``seed`` the seed of the draws;
    ``seconds`` the wall time of the whole family (None: not timed); ``figure`` the
    report's figure of the result as a PNG file's bytes, where the run drew it
    (:func:`~wmr_mujoco.validation.members.run_families`'s ``draw``; None: not drawn).
    """

    scenario: Scenario
    rows: list[Row]
    trace: Trace
    error: str | None = None
    members: list[ScenarioResult] = field(default_factory=list)
    seed: int | None = None
    seconds: float | None = None
    figure: bytes | None = None

    @property
    def passed(self) -> bool:
        """No error and no judged row failed (in any member)."""
        return (self.error is None and all(r.passed is not False for r in self.rows)
                and all(m.passed for m in self.members))


def make_adapter(spec: RobotSpec, scenario: Scenario, model: mujoco.MjModel,
                 params: RobotParams | None = None) -> Adapter:
    """The adapter of the robot ``spec`` for the scenario's kind (default parameters if None).

    Raises:
        ValueError: the robot has no analytic model of that kind.
    """
    return _adapter_factory(spec, scenario)(scenario, model, params)


def _adapter_factory(spec: RobotSpec, scenario: Scenario) -> AdapterFactory:
    """The robot's adapter factory for the scenario's kind.

    Raises:
        ValueError: the robot has no analytic model of that kind.
    """
    factory = spec.adapters.get(scenario.kind)
    if factory is None:
        have = ", ".join(k.value for k in spec.adapters) or "none"
        raise ValueError(f"no {scenario.kind.value} model for robot {scenario.robot!r}; "
                         f"it has: {have}")
    return factory


#: Called after every step with ``(model, data, analytic_state, adapter)``.
Observer = Callable[[mujoco.MjModel, mujoco.MjData, np.ndarray, Adapter], None]


def run_scenario(spec: RobotSpec, s: Scenario,
                 progress: Callable[[str], None] | None = None,
                 observer: Observer | None = None, params: RobotParams | None = None,
                 engine: Engine | str = Engine.ROLLOUT) -> ScenarioResult:
    """Run one scenario; never raises.

    A diverging or failing run comes back as a result with ``error`` set and a failed
    row carrying the reason. ``observer`` (e.g. a video recorder) sees every step;
    ``params`` builds the robot from parameters instead of the checked-in model;
    ``engine`` picks :func:`~wmr_mujoco.sim.engine.simulate`'s stepping (an observer
    forces the Python loop).
    """
    def run() -> ScenarioResult:
        if s.kind is ScenarioKind.MEASUREMENT:
            return _evaluate(s, params)
        prep = prepare(spec, s, params)
        on_step = None
        if observer is not None:
            def on_step(k: int) -> None:
                observer(prep.model, prep.data, prep.analytic[k + 1], prep.adapter)
        states = simulate(prep.model, prep.data, prep.controls, engine, on_step)
        trace = Trace()
        return ScenarioResult(s, measure(prep, states, trace), trace)

    return guarded(s, run, progress)


def guarded(s: Scenario, run: Callable[[], ScenarioResult],
            progress: Callable[[str], None] | None) -> ScenarioResult:
    """``run()``, a divergence or an exception turned into a failed result."""
    try:
        return run()
    except SimulationDivergedError as err:
        reason = f"diverged: {err}"
    except Exception as err:  # a failed scenario becomes a failed row
        reason = f"{type(err).__name__}: {err}"
        if progress:
            progress(traceback.format_exc())
    row = Row(s.robot, s.name, "run", float("nan"), "", None, False, reason)
    return ScenarioResult(s, [row], Trace(), error=reason)


def _evaluate(s: Scenario, params: RobotParams | None) -> ScenarioResult:
    """A measurement scenario through its own ``evaluate``."""
    assert s.evaluate is not None  # guaranteed by Scenario for this kind
    result = s.evaluate(s, params)
    trace = Trace(series=list(result.series))
    return ScenarioResult(s, [Row.of(s.robot, s.name, m) for m in s.opened(result.metrics)],
                          trace)


def schedule(s: Scenario, adapter: Adapter, x0: np.ndarray, dt: float, nstep: int
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Inputs, actuator controls and analytic states on the simulation grid.

    The analytic model does not depend on the simulation, so the whole open-loop schedule
    is known before MuJoCo runs: ``u_k = u(k Δt)``, ``ctrl_k = controls(u_k, x_k)`` and
    ``x_{k+1} = RK4(x_k, u_k)``, or ``adapter.exact_step(x_k, u_k, Δt)`` where the adapter has
    an exact step for a held input; ``adapter.trajectory(x_0, inputs, Δt)`` where it has
    one (the same states, all steps at once), and then ``adapter.controls_on(inputs,
    states)`` where it has one (the same controls, all steps at once).

    Returns:
        ``(inputs (N, m), controls (N, nu), analytic (N + 1, n))``.
    """
    x = np.asarray(x0, float)
    inputs = s.inputs_on(nstep, dt)  # u(k Δt), the floats of s.input_at(k Δt)
    trajectory = getattr(adapter, "trajectory", None)  # every step at once, where it has one
    if trajectory is not None:
        states = np.asarray(trajectory(x, inputs, dt), float)
        controls_on = getattr(adapter, "controls_on", None)  # all at once, where it has one
        if controls_on is not None:
            return inputs, np.asarray(controls_on(inputs, states[:-1]), float), states
        controls = [adapter.controls(u, xk) for u, xk in zip(inputs, states, strict=False)]
        return inputs, np.asarray(controls), states
    step = getattr(adapter, "exact_step", None)  # where the adapter has one
    controls, states = [], [x]
    for u in inputs:
        controls.append(adapter.controls(u, x))
        x = step(x, u, dt) if step is not None else rk4_step(adapter.rhs, x, u, dt)
        states.append(x)
    return inputs, np.asarray(controls), np.asarray(states)


def check_runnable(spec: RobotSpec, s: Scenario) -> None:
    """Check that ``s`` can be run and judged on the robot ``spec``, before any work.

    The input count is the one of the robot's own scenarios of the same kind and frame
    (the adapter's channels); a robot without such a scenario is not checked here.

    Raises:
        ValueError: the robot has no analytic model or no judge for the scenario's kind
            (the message lists the kinds it has), or a wrong number of input channels.
    """
    if s.robot != spec.name:
        raise ValueError(f"{s.key}: a scenario of robot {s.robot!r} given with the spec of "
                         f"{spec.name!r}")
    _adapter_factory(spec, s)
    if spec.judge(s.kind) is None:
        have = [k.value for k in ScenarioKind if k is not ScenarioKind.MEASUREMENT
                and spec.judge(k) is not None]
        raise ValueError(f"robot {s.robot!r} has no judge for {s.kind.value} scenarios; "
                         f"kinds it judges: {', '.join(have) or 'none'}")
    counts = {len(o.inputs) for o in spec.scenarios
              if o.kind is s.kind and o.world_frame == s.world_frame}
    if counts and len(s.inputs) not in counts:
        valid = " or ".join(map(str, sorted(counts)))
        raise ValueError(f"{s.key}: {len(s.inputs)} inputs; robot {s.robot!r} takes {valid} "
                         f"input channels for {s.kind.value} scenarios")


@dataclass
class Prepared:
    """A scenario ready to simulate: settled model and data, and its open-loop schedule."""

    spec: RobotSpec
    scenario: Scenario
    model: mujoco.MjModel
    data: mujoco.MjData
    adapter: Adapter
    inputs: np.ndarray
    controls: np.ndarray
    analytic: np.ndarray


def prepare(spec: RobotSpec, s: Scenario, params: RobotParams | None = None,
            model: mujoco.MjModel | None = None) -> Prepared:
    """Load, settle at rest for ``s.settle`` seconds, and compute the schedule.

    A drawn wheel phase (:data:`~wmr_mujoco.validation.variations.WHEEL_PHASE`) turns the
    adapter's wheel joints by it before the settle.

    ``model``: the robot's compiled model to use (and modify) instead of loading it.
    The scenario is checked against the robot before anything is loaded or simulated.

    Raises:
        ValueError: the robot has no judge for the scenario's kind, or the scenario's
            input count is not the one the robot's analytic model of that kind takes.
    """
    check_runnable(spec, s)
    if model is None:
        model = load(spec, params)
    adapter = make_adapter(spec, s, model, params)
    if adapter.mode is not None:
        set_actuation_mode(model, adapter.mode)
    data = mujoco.MjData(model)
    phase = s.value(WHEEL_PHASE, 0.0)
    if phase:
        add_wheel_phase(model, data, adapter.wheel_joints, phase)
    dt = model.opt.timestep
    nsettle = round(s.settle / dt)
    if nsettle:
        mujoco.mj_step(model, data, nsettle)  # the same steps as one by one
    check_healthy(model, data)
    nstep = round(s.duration / dt)
    inputs, controls, analytic = schedule(s, adapter, adapter.sim_state(model, data), dt, nstep)
    return Prepared(spec, s, model, data, adapter, inputs, controls, analytic)


def measure(prep: Prepared, states: np.ndarray, trace: Trace) -> list[Row]:
    """Judged rows of a simulated scenario (:func:`measure_metrics`)."""
    s = prep.scenario
    return [Row.of(s.robot, s.name, m) for m in measure_metrics(prep, states, trace)]


def measure_metrics(prep: Prepared, states: np.ndarray, trace: Trace) -> list[Metric]:
    """Metrics of a simulated scenario from its states (see :func:`simulate`).

    Every :data:`RECORD_EVERY`-th step is rebuilt as ``mj_step`` left it, from its stored
    start and end states (:func:`~wmr_mujoco.validation.resample.restore_step`: contacts
    and frames of the configuration whose constraints produced the new velocities,
    without solving them again); the robot's probes and the lateral-slip measurement see
    it there (where neither reads it, before every probe's ``after``
    (:func:`first_read`) or without either, the step is not rebuilt), and the pose at the
    step's end is recorded beside the analytic state at the same time (its frames and
    velocities from :func:`sync_kinematics`).

    Raises:
        ValueError: the robot has no judge for the scenario's kind.
    """
    s, model, data, adapter = prep.scenario, prep.model, prep.data, prep.adapter
    spec = prep.spec
    judge = spec.judge(s.kind)
    if judge is None:
        raise ValueError(f"robot {s.robot!r} has no judge for {s.kind.value} scenarios")
    probes: list[Probe] = [p for factory in spec.probes
                           if (p := factory(s, model, adapter, spec.targets)) is not None]
    trace.state_names, trace.state_units = adapter.state_names, adapter.state_units
    nstep = len(prep.controls)
    read_after = first_read(probes, adapter)
    frames_only = getattr(adapter, "frames_only", False)  # sim_state reads frames alone
    dt = model.opt.timestep
    for k in range(nstep):
        if k % RECORD_EVERY != RECORD_EVERY - 1 and k != nstep - 1:
            continue
        if k * dt > read_after:  # else nothing reads the rebuilt step
            _restep(prep, states, k, trace, probes)
        else:
            trace.slip.append(np.zeros(0))
        mujoco.mj_setState(model, data, states[k + 1], STATE_SPEC)
        sync_kinematics(model, data, frames_only)
        trace.time.append(data.time - s.settle)
        trace.sim.append(adapter.sim_state(model, data))
        trace.analytic.append(prep.analytic[k + 1])
    metrics = judge(s, trace, adapter, spec.targets)
    if adapter.lateral_wheels:
        metrics += slip_metrics(trace, adapter.lateral_wheels, spec.targets)
    for probe in probes:
        metrics += probe.metrics()
    return s.opened(metrics)


def first_read(probes: Sequence[Probe], adapter: Adapter) -> float:
    """The time after which a rebuilt step is read: the probes' earliest ``after``, s.

    A probe with an ``after`` attribute ignores the samples at ``t <= after``
    (:class:`~wmr_mujoco.validation.traces.Probe`); one without it reads every sample, as
    does the lateral slip of an adapter's ``lateral_wheels`` (``-inf``). ``inf``: nothing
    reads a rebuilt step.
    """
    if adapter.lateral_wheels:
        return -math.inf
    return min((getattr(p, "after", -math.inf) for p in probes), default=math.inf)


def _restep(prep: Prepared, states: np.ndarray, k: int, trace: Trace,
            probes: Sequence[Probe]) -> None:
    """Step ``k`` as ``mj_step`` left it (:func:`restore_step`): slip and probes see it."""
    model, data = prep.model, prep.data
    data.ctrl[:] = prep.controls[k]
    restore_step(model, data, states[k], states[k + 1])
    trace.slip.append(lateral_slip(model, data, prep.adapter.lateral_wheels))
    sample = Sample(k, k * model.opt.timestep, model, data, prep.inputs[k],
                    prep.controls[k], prep.analytic[k])
    for probe in probes:
        probe.observe(sample)


def run_all(work: Sequence[Job], progress: Callable[[str], None] | None = None,
            on_result: Callable[[ScenarioResult], None] | None = None
            ) -> list[ScenarioResult]:
    """Run every scenario once (its nominal run); a failure does not stop the others.

    :func:`wmr_mujoco.validation.members.run_families` runs their families instead.

    ``progress`` gets one line ``"[k/n] robot/scenario"`` as the k-th result is there
    (numbered by completion), besides the tracebacks of failed runs; ``on_result`` sees
    each result as soon as it is there.
    """
    results = []
    for spec, s in work:
        result = run_scenario(spec, s, progress)
        results.append(result)
        announce(result, len(results), len(work), progress, on_result)
    return results
