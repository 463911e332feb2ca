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
import traceback
from collections.abc import Callable, Sequence
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
            return ad.OmniDynamicsAdapter(ad.omni_dynamics_from_model(model, params))
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
    jacp = np.zeros((3, model.nv))
    for i, name in enumerate(wheels):
        joint = model.joint(name)
        body = int(joint.bodyid[0])
        axle = data.xaxis[joint.id]
        for c in data.contact[:data.ncon]:
            if body in (model.geom_bodyid[c.geom1], model.geom_bodyid[c.geom2]):
                mujoco.mj_jac(model, data, jacp, None, c.pos, body)
                out[i] = float(axle @ (jacp @ data.qvel))
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
                 observer: Observer | None = None, params: Any = None) -> ScenarioResult:
    """Run one scenario through MuJoCo and the analytic model; never raises.

    A diverging or failing run comes back as a result with ``error`` set and a failed
    row carrying the reason. ``observer`` (e.g. a video recorder) sees every step;
    ``params`` builds the robot from parameters instead of the checked-in model.
    """
    trace = Trace()
    try:
        rows = _run(s, trace, observer, params)
        return ScenarioResult(s, rows, trace)
    except SimulationDivergedError as err:
        reason = f"diverged: {err}"
    except Exception as err:  # a failed scenario becomes a failed row
        reason = f"{type(err).__name__}: {err}"
        if progress:
            progress(traceback.format_exc())
    row = Row(s.robot, s.name, "run", float("nan"), "", None, False, reason)
    return ScenarioResult(s, [row], trace, error=reason)


def _run(s: sc.Scenario, trace: Trace, observer: Observer | None = None,
         params: Any = None) -> list[Row]:
    model = load(s.robot, params)
    adapter = make_adapter(s, model, params)
    set_actuation_mode(model, adapter.mode)
    data = mujoco.MjData(model)
    dt = model.opt.timestep
    for _ in range(round(s.settle / dt)):
        mujoco.mj_step(model, data)
    check_healthy(model, data)
    x = adapter.sim_state(model, data).astype(float)
    nstep = round(s.duration / dt)
    wheel_dofs = [model.jnt_dofadr[model.joint(j).id] for j in adapter.wheel_joints]
    info = layout_from_model(model, adapter.wheel_joints) if s.robot == "omni3" else None
    free_wheel, wheel_rate_err, roller_err = [], [], []
    for k in range(nstep):
        t = k * dt
        u = s.input_at(t)
        ctrl = adapter.controls(u, x)
        data.ctrl[:] = ctrl
        mujoco.mj_step(model, data)
        x = rk4_step(adapter.rhs, x, u, dt)
        if observer is not None:
            observer(model, data, x, adapter)
        if k % 5 == 4 or k == nstep - 1:
            check_healthy(model, data)
            trace.time.append(data.time - s.settle)
            trace.sim.append(adapter.sim_state(model, data))
            trace.analytic.append(x.copy())
            trace.slip.append(lateral_slip(model, data, adapter.lateral_wheels))
            rates = data.qvel[wheel_dofs]
            steady = t > 1.0
            if s.robot == "tricycle" and steady and abs(rates[0]) > 1.0:
                p = adapter.params
                k_icr = p.track / (2 * p.wheelbase) * math.tan(data.joint("steer").qpos[0])
                predicted = rates[0] * (1 + k_icr) / (1 - k_icr)
                free_wheel.append((rates[1] - predicted) / predicted)
            if info is not None and adapter.mode == "rate" and steady:
                if np.linalg.norm(ctrl) > 0.5:
                    wheel_rate_err.append(np.linalg.norm(rates - ctrl) / np.linalg.norm(ctrl))
                twist = adapter.twist(u, x)
                roller_err += roller_rate_errors(model, data, info,
                                                 roller_slide_speeds(adapter.layout, twist))
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
    limit = OmniParams().sim.friction * adapter.dynamics.mass * 9.81 / 3.0
    rows.append(Row.judged(s.robot, s.name, "largest traction / μN", float(
        np.max(np.abs(forces)) / limit), "", 1.0))
    return rows


def run_all(scenarios: Sequence[sc.Scenario],
            progress: Callable[[str], None] | None = None) -> list[ScenarioResult]:
    """Run every scenario (a failure does not stop the others)."""
    results = []
    for i, s in enumerate(scenarios, 1):
        if progress:
            progress(f"[{i}/{len(scenarios)}] {s.key}")
        results.append(run_scenario(s, progress))
    return results
