"""Contact physics against the analytic models: run scenarios, measure, judge.

For each :class:`~wmr_mujoco.scenarios.Scenario` the simulation and the analytic model
advance together on MuJoCo's time grid: at step k the input ``u(t_k)`` becomes actuator
controls for ``mj_step`` and is held over the step in the analytic model's RK4 step
(:func:`wmr_mujoco.analytic.integrate.rk4_step`), from the same settled initial state.

Metrics (one :class:`Row` each; ``target`` None means reported, not judged):
    * final and RMS position error (m, % of path), final heading error;
    * RMS lateral slip speed at every conventional wheel's contact, measured in the
      physics as the contact point's velocity along the wheel axle (the non-holonomic
      constraint residual);
    * tricycle: free-wheel rate against the ICR prediction from the measured driven wheel
      and steering angle;
    * omni: wheel rates against ``H ν`` and roller spin rates against slide speed / ρ;
    * dynamic runs: single-wheel acceleration against ``τR/(J + mR²)``, omni body
      velocities against the reduced Lagrange equations after 2 s of torques.
"""

from __future__ import annotations

import math
import os
import traceback
from collections.abc import Callable, Sequence
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from wmr_mujoco import adapters as ad
from wmr_mujoco import scenarios as sc
from wmr_mujoco.actuation import set_actuation_mode
from wmr_mujoco.analytic.integrate import rk4_step
from wmr_mujoco.analytic.omni_kinematics import roller_slide_speeds
from wmr_mujoco.loading import load
from wmr_mujoco.omni_trials import layout_from_model, roller_rate_errors
from wmr_mujoco.params import OmniParams
from wmr_mujoco.registry import get_spec
from wmr_mujoco.simulation import SimulationDivergedError, check_healthy


@dataclass(frozen=True)
class Row:
    """One metric of one scenario."""

    robot: str
    scenario: str
    metric: str
    value: float
    unit: str
    target: float | None = None
    passed: bool | None = None
    note: str = ""

    @staticmethod
    def judged(robot: str, scenario: str, metric: str, value: float, unit: str,
               target: float | None) -> Row:
        """A row that passes when ``|value| <= target`` (and is finite)."""
        passed = None if target is None else bool(np.isfinite(value) and abs(value) <= target)
        return Row(robot, scenario, metric, float(value), unit, target, passed)


@dataclass
class Trace:
    """Time series of one run, for plots."""

    time: list[float] = field(default_factory=list)
    sim: list[np.ndarray] = field(default_factory=list)
    analytic: list[np.ndarray] = field(default_factory=list)
    slip: list[np.ndarray] = field(default_factory=list)

    def arrays(self) -> dict[str, np.ndarray]:
        """The series as arrays."""
        return {"time": np.asarray(self.time), "sim": np.asarray(self.sim),
                "analytic": np.asarray(self.analytic), "slip": np.asarray(self.slip)}


@dataclass
class ScenarioResult:
    """Rows and trace of one scenario (``error`` set when it diverged or raised)."""

    scenario: sc.Scenario
    rows: list[Row]
    trace: Trace
    error: str | None = None

    @property
    def passed(self) -> bool:
        """No error and no judged row failed."""
        return self.error is None and all(r.passed is not False for r in self.rows)


def make_adapter(scenario: sc.Scenario, model: mujoco.MjModel, params: Any = None
                 ) -> ad.Adapter:
    """The adapter of a scenario's robot and kind (default parameters if None)."""
    params = params if params is not None else get_spec(scenario.robot).params_type()
    if scenario.kind == "dynamic":
        if scenario.robot == "disc":
            return ad.DiscDynamics(params)
        if scenario.robot == "omni3":
            return ad.OmniDynamicsAdapter(ad.omni_dynamics_from_model(model, params),
                                          friction=params.sim.friction)
    elif scenario.kind == "kinematic":
        if scenario.robot == "omni3":
            return ad.OmniKinematics(params, world_frame=scenario.world_frame)
        kinematic = {"disc": ad.DiscKinematics, "bicycle": ad.BicycleKinematics,
                     "tricycle": ad.TricycleKinematics}
        if scenario.robot in kinematic:
            return kinematic[scenario.robot](params)
    raise ValueError(f"no {scenario.kind} model for robot {scenario.robot!r}")


def lateral_slip(model: mujoco.MjModel, data: mujoco.MjData,
                 wheels: Sequence[str]) -> np.ndarray:
    """Speed of each wheel's contact point along its axle (0 without contact), m/s."""
    out = np.zeros(len(wheels))
    if not wheels or data.ncon == 0:
        return out
    jacp = np.zeros((3, model.nv))
    contact_bodies = model.geom_bodyid[data.contact.geom[:data.ncon]]
    positions = data.contact.pos[:data.ncon]
    for i, name in enumerate(wheels):
        jid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
        body = int(model.jnt_bodyid[jid])
        for c in np.flatnonzero((contact_bodies == body).any(axis=1)):
            mujoco.mj_jac(model, data, jacp, None, positions[c], body)
            out[i] = float(data.xaxis[jid] @ (jacp @ data.qvel))
    return out


def _path_length(xy: np.ndarray) -> float:
    return float(np.sum(np.linalg.norm(np.diff(xy, axis=0), axis=1)))


def _wrap_deg(angle: float) -> float:
    return float(np.degrees(np.angle(np.exp(1j * angle))))


def _kinematic_rows(s: sc.Scenario, tr: dict[str, np.ndarray], adapter: ad.Adapter,
                    extra: dict[str, float]) -> list[Row]:
    sim, ana = tr["sim"], tr["analytic"]
    err = np.linalg.norm(sim[:, :2] - ana[:, :2], axis=1)
    path = _path_length(ana[:, :2])
    target = sc.POSITION_PCT[s.robot]
    rows = []
    pct = 100.0 * err[-1] / path if path > 1e-3 else float("nan")
    if path > 1e-3:
        rows.append(Row.judged(s.robot, s.name, "final position error", pct, "% of path",
                               target))
    else:  # turning in place: judge the centre's drift against 1 % of the wheel distance
        rows.append(Row.judged(s.robot, s.name, "final centre drift", err[-1], "m",
                               0.01 * OmniParams().wheel_distance))
    rows.append(Row.judged(s.robot, s.name, "final position error", err[-1], "m", None))
    rows.append(Row.judged(s.robot, s.name, "RMS position error", float(np.sqrt(np.mean(
        err**2))), "m", None))
    heading_target = sc.HEADING_DEG_OMNI if s.robot == "omni3" else None
    rows.append(Row.judged(s.robot, s.name, "final heading error",
                           _wrap_deg(sim[-1, 2] - ana[-1, 2]), "deg", heading_target))
    rows.append(Row.judged(s.robot, s.name, "path length", path, "m", None))
    if adapter.lateral_wheels:
        slip = tr["slip"]
        for i, wheel in enumerate(adapter.lateral_wheels):
            rms = float(np.sqrt(np.mean(slip[:, i] ** 2)))
            rows.append(Row.judged(s.robot, s.name, f"lateral slip RMS, {wheel}", rms, "m/s",
                                   sc.LATERAL_SLIP_RMS))
    for metric, (value, unit, target) in extra.items():
        rows.append(Row.judged(s.robot, s.name, metric, value, unit, target))
    return rows


#: Called after every step with ``(model, data, analytic_state, adapter)``.
Observer = Callable[[mujoco.MjModel, mujoco.MjData, np.ndarray, "ad.Adapter"], None]


def run_scenario(s: sc.Scenario, progress: Callable[[str], None] | None = None,
                 observer: Observer | None = None, params: Any = None,
                 engine: str = "rollout") -> ScenarioResult:
    """Run one scenario through MuJoCo and the analytic model; never raises.

    A diverging or failing run comes back as a result with ``error`` set and a failed
    row carrying the reason. ``observer`` (e.g. a video recorder) sees every step;
    ``params`` builds the robot from parameters instead of the checked-in model;
    ``engine`` picks :func:`simulate`'s stepping (an observer forces the Python loop).
    """
    trace = Trace()
    try:
        rows = _run(s, trace, observer, params, engine)
        return ScenarioResult(s, rows, trace)
    except SimulationDivergedError as err:
        reason = f"diverged: {err}"
    except Exception as err:  # a failed scenario becomes a failed row
        reason = f"{type(err).__name__}: {err}"
        if progress:
            progress(traceback.format_exc())
    row = Row(s.robot, s.name, "run", float("nan"), "", None, False, reason)
    return ScenarioResult(s, [row], trace, error=reason)


#: Metrics are recorded every this many steps.
RECORD_EVERY = 5
#: MuJoCo state recorded after every step (what ``mujoco.rollout`` returns).
STATE_SPEC = mujoco.mjtState.mjSTATE_FULLPHYSICS
#: How the simulation is stepped: a Python ``mj_step`` loop or ``mujoco.rollout``.
ENGINES = ("rollout", "loop")


def schedule(s: sc.Scenario, adapter: ad.Adapter, x0: np.ndarray, dt: float, nstep: int
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Inputs, actuator controls and analytic states on the simulation grid.

    The analytic model does not depend on the simulation, so the whole open-loop schedule
    is known before MuJoCo runs: ``u_k = u(k Δt)``, ``ctrl_k = controls(u_k, x_k)`` and
    ``x_{k+1} = RK4(x_k, u_k)``.

    Returns:
        ``(inputs (N, m), controls (N, nu), analytic (N + 1, n))``.
    """
    x = np.asarray(x0, float)
    inputs, controls, states = [], [], [x]
    for k in range(nstep):
        u = s.input_at(k * dt)
        inputs.append(u)
        controls.append(adapter.controls(u, x))
        x = rk4_step(adapter.rhs, x, u, dt)
        states.append(x)
    return np.asarray(inputs), np.asarray(controls), np.asarray(states)


def simulate(model: mujoco.MjModel, data: mujoco.MjData, controls: np.ndarray,
             engine: str = "rollout", on_step: Callable[[int], None] | None = None
             ) -> np.ndarray:
    """Apply ``controls`` from the state in ``data``; return the state after every step.

    ``engine="loop"`` steps in Python (and calls ``on_step(k)`` after step k, with
    ``data`` live); ``"rollout"`` hands the whole open-loop sequence to
    ``mujoco.rollout`` in C, starting from the same state and solver warm start, so the
    two give bit-identical states. Returns an (N + 1, nstate) array of
    ``mjSTATE_FULLPHYSICS`` states, the initial one first.

    Raises:
        ValueError: unknown engine.
        SimulationDivergedError: NaN or MuJoCo warnings.
    """
    if engine not in ENGINES:
        raise ValueError(f"engine = {engine!r}; valid engines are {', '.join(ENGINES)}")
    size = mujoco.mj_stateSize(model, STATE_SPEC)
    states = np.empty((len(controls) + 1, size))
    mujoco.mj_getState(model, data, states[0], STATE_SPEC)
    if engine == "rollout" and on_step is None:
        from mujoco import rollout

        rolled, _ = rollout.rollout(model, data, states[0], controls[None],
                                    initial_warmstart=data.qacc_warmstart.copy()[None])
        states[1:] = rolled[0]
        check_healthy(model, data)
        if not np.all(np.isfinite(states)):
            raise SimulationDivergedError(f"rollout of {len(controls)} steps produced "
                                          f"non-finite states")
        return states
    for k, ctrl in enumerate(controls):
        data.ctrl[:] = ctrl
        mujoco.mj_step(model, data)
        mujoco.mj_getState(model, data, states[k + 1], STATE_SPEC)
        if on_step is not None:
            on_step(k)
        if k % RECORD_EVERY == RECORD_EVERY - 1:
            check_healthy(model, data)
    check_healthy(model, data)
    return states


@dataclass
class Prepared:
    """A scenario ready to simulate: settled model and data, and its open-loop schedule."""

    scenario: sc.Scenario
    model: mujoco.MjModel
    data: mujoco.MjData
    adapter: ad.Adapter
    inputs: np.ndarray
    controls: np.ndarray
    analytic: np.ndarray


def prepare(s: sc.Scenario, params: Any = None) -> Prepared:
    """Load, settle at rest for ``s.settle`` seconds, and compute the schedule."""
    model = load(s.robot, params)
    adapter = make_adapter(s, model, params)
    set_actuation_mode(model, adapter.mode)
    data = mujoco.MjData(model)
    dt = model.opt.timestep
    for _ in range(round(s.settle / dt)):
        mujoco.mj_step(model, data)
    check_healthy(model, data)
    nstep = round(s.duration / dt)
    inputs, controls, analytic = schedule(s, adapter, adapter.sim_state(model, data), dt, nstep)
    return Prepared(s, model, data, adapter, inputs, controls, analytic)


def _run(s: sc.Scenario, trace: Trace, observer: Observer | None = None,
         params: Any = None, engine: str = "rollout") -> list[Row]:
    prep = prepare(s, params)
    on_step = None
    if observer is not None:
        def on_step(k: int) -> None:
            observer(prep.model, prep.data, prep.analytic[k + 1], prep.adapter)
    states = simulate(prep.model, prep.data, prep.controls, engine, on_step)
    return measure(prep, states, trace)


def measure(prep: Prepared, states: np.ndarray, trace: Trace) -> list[Row]:
    """Metrics of a simulated scenario from its states (see :func:`simulate`)."""
    s, model, data, adapter = prep.scenario, prep.model, prep.data, prep.adapter
    inputs, controls, analytic = prep.inputs, prep.controls, prep.analytic
    dt = model.opt.timestep
    nstep = len(controls)
    wheel_dofs = [model.jnt_dofadr[model.joint(j).id] for j in adapter.wheel_joints]
    info = layout_from_model(model, adapter.wheel_joints) if s.robot == "omni3" else None
    free_wheel, wheel_rate_err, roller_err = [], [], []
    recorded = [k for k in range(nstep) if k % RECORD_EVERY == RECORD_EVERY - 1
                or k == nstep - 1]
    for k in recorded:
        # Redo step k from its stored start: the contacts and frames then belong to the
        # configuration whose constraints produced the new velocities, as in the loop.
        # The warm start is not part of the stored state: start the solver from zero so
        # that the measurement does not depend on how the states were produced.
        mujoco.mj_setState(model, data, states[k], STATE_SPEC)
        data.qacc_warmstart[:] = 0.0
        data.ctrl[:] = controls[k]
        mujoco.mj_step(model, data)
        check_healthy(model, data)
        u, ctrl, x = inputs[k], controls[k], analytic[k + 1]
        trace.slip.append(lateral_slip(model, data, adapter.lateral_wheels))
        rates = data.qvel[wheel_dofs].copy()
        steady = k * dt > 1.0
        if s.robot == "tricycle" and steady and abs(rates[0]) > 1.0:
            p = adapter.params
            k_icr = p.track / (2 * p.wheelbase) * math.tan(data.joint("steer").qpos[0])
            predicted = rates[0] * (1 + k_icr) / (1 - k_icr)
            free_wheel.append((rates[1] - predicted) / predicted)
        if info is not None and adapter.mode == "rate" and steady:
            if np.linalg.norm(ctrl) > 0.5:
                wheel_rate_err.append(np.linalg.norm(rates - ctrl) / np.linalg.norm(ctrl))
            twist = adapter.twist(u, analytic[k])
            roller_err += roller_rate_errors(model, data, info,
                                             roller_slide_speeds(adapter.layout, twist))
        # Pose at the end of the step, beside the analytic state at the same time.
        mujoco.mj_setState(model, data, states[k + 1], STATE_SPEC)
        mujoco.mj_forward(model, data)
        trace.time.append(data.time - s.settle)
        trace.sim.append(adapter.sim_state(model, data))
        trace.analytic.append(x)
    tr = trace.arrays()
    if s.kind == "dynamic":
        return _dynamic_rows(s, tr, adapter)
    extra: dict[str, tuple[float, str, float | None]] = {}
    if free_wheel:
        extra["free-wheel rate error vs ICR (RMS)"] = (
            100.0 * float(np.sqrt(np.mean(np.square(free_wheel)))), "%", None)
    if wheel_rate_err:
        extra["wheel rate error vs J ν (RMS)"] = (
            100.0 * float(np.sqrt(np.mean(np.square(wheel_rate_err)))), "%", None)
    if roller_err:
        extra["roller rate error (median)"] = (100.0 * float(np.median(roller_err)), "%",
                                               sc.ROLLER_RATE_PCT)
    return _kinematic_rows(s, tr, adapter, extra)


def _dynamic_rows(s: sc.Scenario, tr: dict[str, np.ndarray], adapter: ad.Adapter
                  ) -> list[Row]:
    t, sim, ana = tr["time"], tr["sim"], tr["analytic"]
    if s.robot == "disc":
        steady = t > 0.5
        measured = float(np.polyfit(t[steady], sim[steady, 1], 1)[0])
        expected = adapter.wheel.rolling_acceleration(s.input_at(0.0)[0])
        return [
            Row.judged(s.robot, s.name, "rolling acceleration error",
                       100.0 * (measured - expected) / expected, "%", sc.WHEEL_ACCEL_PCT),
            Row.judged(s.robot, s.name, "rolling acceleration (MuJoCo)", measured, "m/s²",
                       None),
            Row.judged(s.robot, s.name, "rolling acceleration τR/(J+mR²)", expected, "m/s²",
                       None),
            Row.judged(s.robot, s.name, "traction limit margin",
                       adapter.wheel.max_rolling_torque / abs(s.input_at(0.0)[0]), "×", None),
        ]
    nu_sim, nu_ana = sim[-1, 3:6], ana[-1, 3:6]
    rel = float(np.linalg.norm(nu_sim - nu_ana) / np.linalg.norm(nu_ana))
    rows = [Row.judged(s.robot, s.name, "body velocity error after 2 s", 100.0 * rel, "%",
                       sc.OMNI_VELOCITY_PCT)]
    for i, name in enumerate(("u", "v", "r")):
        rows.append(Row.judged(s.robot, s.name, f"{name}: MuJoCo / Lagrange",
                               nu_sim[i] / nu_ana[i] if abs(nu_ana[i]) > 1e-9 else float("nan"),
                               "ratio", None))
    forces = adapter.dynamics.traction_forces(nu_ana, s.input_at(s.duration))
    limit = adapter.friction * adapter.dynamics.mass * 9.81 / 3.0
    rows.append(Row.judged(s.robot, s.name, "largest traction / μN", float(
        np.max(np.abs(forces)) / limit), "", 1.0))
    return rows


def simulate_batch(prepared: Sequence[Prepared], nthread: int | None = None
                   ) -> list[np.ndarray]:
    """Simulate scenarios of one robot and actuation mode in one threaded rollout.

    All start from the same settled state (same model, same settle), so they share one
    model; shorter schedules are padded with their last control and cut afterwards. Each
    trajectory is what :func:`simulate` gives alone, bit for bit.

    Raises:
        SimulationDivergedError: a trajectory has non-finite states (the caller reruns
            the group one by one to say which).
    """
    from mujoco import rollout

    first = prepared[0]
    model = first.model
    nstep = max(len(p.controls) for p in prepared)
    controls = np.stack([np.concatenate([p.controls, np.repeat(p.controls[-1:], nstep
                                                                - len(p.controls), axis=0)])
                         for p in prepared])
    size = mujoco.mj_stateSize(model, STATE_SPEC)
    initial = np.zeros(size)
    mujoco.mj_getState(model, first.data, initial, STATE_SPEC)
    nthread = max(1, min(nthread or os.cpu_count() or 1, len(prepared)))
    datas = [mujoco.MjData(model) for _ in range(nthread)]
    rolled, _ = rollout.rollout(model, datas if nthread > 1 else datas[0],
                                np.tile(initial, (len(prepared), 1)), controls,
                                initial_warmstart=np.tile(first.data.qacc_warmstart,
                                                          (len(prepared), 1)),
                                persistent_pool=nthread > 1)
    for d in datas:
        check_healthy(model, d)
    out = []
    for p, traj in zip(prepared, rolled, strict=True):
        states = np.concatenate([initial[None], traj[:len(p.controls)]])
        if not np.all(np.isfinite(states)):
            raise SimulationDivergedError(f"{p.scenario.key}: non-finite states")
        out.append(states)
    return out


def batch_key(s: sc.Scenario) -> tuple[str, str, float]:
    """Scenarios with equal keys share one model and settled start: one rollout batch."""
    return s.robot, s.kind, s.settle


def run_all(scenarios: Sequence[sc.Scenario],
            progress: Callable[[str], None] | None = None,
            engine: str = "rollout") -> list[ScenarioResult]:
    """Run every scenario; a failure does not stop the others.

    With ``engine="rollout"``, scenarios with the same :func:`batch_key` are simulated
    together in one multi-threaded ``mujoco.rollout``, and the batches are pipelined:
    while MuJoCo's threads (which release the GIL) simulate one batch, Python computes the
    next batch's analytic schedule, then measures the finished ones. A batch that fails is
    rerun one scenario at a time so that each failure is attributed. ``"loop"`` steps each
    scenario in Python, one after the other.
    """
    if engine not in ENGINES:
        raise ValueError(f"engine = {engine!r}; valid engines are {', '.join(ENGINES)}")
    results = _run_batched(scenarios, progress) if engine == "rollout" else {}
    for i, s in enumerate(scenarios):
        if i not in results:
            if progress:
                progress(f"[{i + 1}/{len(scenarios)}] {s.key}")
            results[i] = run_scenario(s, progress, engine=engine)
    return [results[i] for i in range(len(scenarios))]


def _run_batched(scenarios: Sequence[sc.Scenario], progress: Callable[[str], None] | None
                 ) -> dict[int, ScenarioResult]:
    """The scenarios that ran cleanly in batches, by index; failures are left out."""
    groups: dict[tuple[str, str, float], list[int]] = {}
    for i, s in enumerate(scenarios):
        groups.setdefault(batch_key(s), []).append(i)
    # One core stays with the Python thread that schedules and measures.
    nthread = max(1, (os.cpu_count() or 1) - 1)
    results: dict[int, ScenarioResult] = {}
    pending: list[tuple[list[tuple[int, Prepared]], Future[list[np.ndarray]]]] = []
    with ThreadPoolExecutor(max_workers=1, thread_name_prefix="wmr-rollout") as pool:
        for members in groups.values():
            prepared = []
            for i in members:
                try:
                    prepared.append((i, prepare(scenarios[i])))
                except Exception:  # reported by the one-at-a-time rerun
                    continue
            if prepared:
                pending.append((prepared, pool.submit(simulate_batch,
                                                      [p for _, p in prepared], nthread)))
        for prepared, future in pending:
            try:
                batch = future.result()
            except Exception:
                continue
            for (i, prep), states in zip(prepared, batch, strict=True):
                if progress:
                    progress(f"[{i + 1}/{len(scenarios)}] {prep.scenario.key}")
                trace = Trace()
                try:
                    results[i] = ScenarioResult(prep.scenario, measure(prep, states, trace),
                                                trace)
                except Exception:
                    continue
    return results
