"""Scenarios and measurements of the caster robots: diffdrive, single_steer, double_steer.

Each scenario (a :class:`wmr_mujoco.scenarios.Scenario`, as data) runs through MuJoCo and
through the analytic model on the same time grid with the same zero-order-hold inputs
(:func:`wmr_mujoco.validation.schedule` and :func:`~wmr_mujoco.validation.simulate`), from
the same settled start. :func:`measure` returns judged metrics as
``(metric, value, unit, target, basis)`` tuples plus the time series. Run
``python -m wmr_mujoco.wheeled_scenarios`` for the table.

Inputs (lecture terms):
    diffdrive:     (v, ω)        midpoint speed and yaw rate; wheels at v ∓ ω b/2
    single_steer:  (v_w, ω)      ground speed of the steered wheel, steering rate
    double_steer:  (v₁, ω₁, ω₂)  front wheel ground speed, front and rear steering rates;
                                 the rear wheel turns at v₁ cos β₁ / cos β₂ (one ICR)

Path: the mean distance rolled by the driven wheels' contact points in the analytic
model, ``∫ mean_i |v_i| dt``; for the differential drive spinning in place it is the arc
each wheel rolls, so "% of path" stays meaningful where the midpoint does not move.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from wmr_mujoco.actuation import set_actuation_mode
from wmr_mujoco.analytic import diffdrive, steered
from wmr_mujoco.builders import common
from wmr_mujoco.builders.scene import add_scene
from wmr_mujoco.params_wheeled import (
    DIFFDRIVE,
    DOUBLE_STEER,
    SINGLE_STEER,
    DiffDriveParams,
    DoubleSteerParams,
    SingleSteerParams,
)
from wmr_mujoco.scenarios import Scenario
from wmr_mujoco.signals import Sine, const, pulses
from wmr_mujoco.simulation import check_healthy
from wmr_mujoco.validation import lateral_slip, schedule, simulate
from wmr_mujoco.wheeled_registry import SPECS, get_spec

#: Requirements (issue 15): position error ≤ 0.5 % of path (final and worst over the run),
#: lateral slip RMS ≤ 1 mm/s at every conventional wheel.
POSITION_PCT = 0.5
LATERAL_SLIP_RMS = 1e-3
REQUIREMENT = "requirement (issue 15)"

ROBOTS = tuple(SPECS)


def _check_robot(robot: str) -> None:
    get_spec(robot)


def build_scene(robot: str, params: Any = None) -> Any:
    """The robot's mjcf root with floor and light (defaults if ``params`` is None)."""
    spec = get_spec(robot)
    params = spec.params_type() if params is None else params
    if not isinstance(params, spec.params_type):
        raise ValueError(f"params for {robot!r} must be a {spec.params_type.__name__}, "
                         f"got {type(params).__name__}")
    root = spec.build(params)
    root.model = f"{root.model} scene"
    add_scene(root)
    return root


def load(robot: str, params: Any = None) -> mujoco.MjModel:
    """The checked-in ``models/<robot>/scene.xml``, or the scene built from ``params``."""
    spec = get_spec(robot)
    if params is None:
        path = spec.scene_path
        if not path.is_file():
            raise FileNotFoundError(f"{path} missing; run `python -m wmr_mujoco.wheeled_export`")
        return mujoco.MjModel.from_xml_path(str(path))
    return mujoco.MjModel.from_xml_string(common.to_xml(build_scene(robot, params)))


def _yaw(quat: np.ndarray) -> float:
    w, x, y, z = quat
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def chassis_pose(data: mujoco.MjData) -> np.ndarray:
    """``(x, y, ψ)`` of the chassis origin (the ``base`` site) from its free joint."""
    return np.array([data.qpos[0], data.qpos[1], _yaw(data.qpos[3:7])])


# ---- adapters (the :class:`wmr_mujoco.adapters.Adapter` protocol) --------------------

@dataclass(frozen=True)
class DiffDriveKinematics:
    """``x = (x, y, ψ)`` of the axle midpoint; ``u = (v, ω)``; controls ``(v_L/R, v_R/R)``."""

    params: DiffDriveParams = DIFFDRIVE
    robot: str = "diffdrive"
    mode: str = "rate"
    state_names: tuple[str, ...] = ("x", "y", "heading")
    wheel_joints: tuple[str, ...] = ("left_wheel", "right_wheel")
    lateral_wheels: tuple[str, ...] = ("left_wheel", "right_wheel")

    def wheel_speeds(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Ground speeds of the driven wheels."""
        return np.array(diffdrive.wheel_speeds(u[0], u[1], self.params.track))

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Actuator controls for input ``u``."""
        return self.wheel_speeds(u, analytic_state) / self.params.wheel.radius

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Analytic state derivative."""
        return diffdrive.rates(x, self.wheel_speeds(u, x), self.params.track)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """The analytic state's quantities read from the simulation."""
        return chassis_pose(data)


@dataclass(frozen=True)
class SingleSteerDynamics:
    """``x = (x, y, ψ, β, p)`` of P; ``u = (v_w, ω)``; controls ``(v_w/R, ω)``."""

    params: SingleSteerParams = SINGLE_STEER
    robot: str = "single_steer"
    mode: str = "rate"
    state_names: tuple[str, ...] = ("x", "y", "heading", "steer", "momentum")
    wheel_joints: tuple[str, ...] = ("drive_wheel",)
    lateral_wheels: tuple[str, ...] = ("drive_wheel",)

    @property
    def inertia(self) -> steered.SleighInertia:
        """Mass data for the sleigh equations."""
        return steered.sleigh_inertia(self.params)

    def wheel_speeds(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Ground speed of the driven wheel."""
        return np.array([u[0]])

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Actuator controls for input ``u``."""
        return np.array([u[0] / self.params.wheel.radius, u[1]])

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Analytic state derivative."""
        return steered.single_rates(x, u, self.inertia)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """The analytic state's quantities read from the simulation."""
        beta = data.joint("drive_steer").qpos[0]
        v_w = data.joint("drive_wheel").qvel[0] * self.params.wheel.radius
        mom = steered.single_momentum(data.qvel[5], v_w, beta,
                                      data.joint("drive_steer").qvel[0], self.inertia)
        return np.append(chassis_pose(data), [beta, mom])


@dataclass(frozen=True)
class DoubleSteerKinematics:
    """``x = (x, y, ψ, β₁, β₂)`` of the midpoint; ``u = (v₁, ω₁, ω₂)``.

    Controls, in actuator order: ``(v₁/R, ω₁, v₂/R, ω₂)`` with ``v₂`` from the analytic
    steering angles (an open-loop schedule known in advance).
    """

    params: DoubleSteerParams = DOUBLE_STEER
    robot: str = "double_steer"
    mode: str = "rate"
    state_names: tuple[str, ...] = ("x", "y", "heading", "front steer", "rear steer")
    wheel_joints: tuple[str, ...] = ("front_wheel", "rear_wheel")
    lateral_wheels: tuple[str, ...] = ("front_wheel", "rear_wheel")

    def wheel_speeds(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Ground speeds ``(v₁, v₂)`` of the front and rear wheels."""
        x = analytic_state
        return np.array([u[0], steered.double_rear_speed(u[0], x[3], x[4])])

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Actuator controls for input ``u``."""
        v = self.wheel_speeds(u, analytic_state) / self.params.wheel.radius
        return np.array([v[0], u[1], v[1], u[2]])

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Analytic state derivative."""
        return steered.double_rates(x, u, self.params.half_wheelbase)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """The analytic state's quantities read from the simulation."""
        return np.append(chassis_pose(data), [data.joint("front_steer").qpos[0],
                                              data.joint("rear_steer").qpos[0]])


ADAPTERS = {"diffdrive": DiffDriveKinematics, "single_steer": SingleSteerDynamics,
            "double_steer": DoubleSteerKinematics}


def make_adapter(robot: str, params: Any = None) -> Any:
    """The adapter of ``robot`` (default parameters if None)."""
    _check_robot(robot)
    cls = ADAPTERS[robot]
    return cls() if params is None else cls(params)


# ---- scenarios ---------------------------------------------------------------------

def _steer(angle: float, start: float = 0.0, time: float = 0.5) -> Any:
    """Steering-rate pulse turning the steering by ``angle`` in ``time`` seconds."""
    return pulses((start, start + time, angle / time))


SCENARIOS: tuple[Scenario, ...] = (
    # Differential drive: (v, ω) of the axle midpoint.
    Scenario("diffdrive", "straight", (const(0.5, 0.5), const(0.0)), duration=6.0),
    Scenario("diffdrive", "arc", (const(0.5, 0.5), const(0.5, 0.5)), duration=8.0),
    Scenario("diffdrive", "spin in place", (const(0.0), const(1.5, 0.5)), duration=6.0),
    # ω = ω₀ sin(2πt/T) at constant v: the heading swings ±ω₀T/2π and returns, two
    # loops traced in opposite senses: a figure eight.
    Scenario("diffdrive", "figure eight", (const(0.5, 0.5), Sine(1.2, 8.0)), duration=16.0),
    # (2,1): (v_w, ω); the casters lead, the steered wheel pushes from behind.
    Scenario("single_steer", "straight", (const(0.4, 0.5), const(0.0)), duration=6.0),
    Scenario("single_steer", "crab 0.5 rad", (const(0.4, 0.5), _steer(0.5, 1.0)),
             duration=6.0),
    Scenario("single_steer", "slalom", (const(0.4, 0.5), Sine(0.6, 3.0)), duration=9.0),
    # (1,2): (v₁, ω₁, ω₂); steering first (at rest), then speed.
    Scenario("double_steer", "straight", (const(0.4, 0.5), const(0.0), const(0.0)),
             duration=6.0),
    Scenario("double_steer", "turn ±0.3 rad", (const(0.4, 0.5, ), _steer(0.3), _steer(-0.3)),
             duration=8.0),
    Scenario("double_steer", "crab 0.5 rad", (const(0.4, 0.5), _steer(0.5), _steer(0.5)),
             duration=6.0),
    Scenario("double_steer", "tight turn ±1 rad", (const(0.3, 0.5), _steer(1.0), _steer(-1.0)),
             duration=6.0),
)


def scenarios_for(robot: str | None = None) -> list[Scenario]:
    """Scenarios of ``robot`` (all if None)."""
    if robot is not None:
        _check_robot(robot)
    return [s for s in SCENARIOS if robot is None or s.robot == robot]


# ---- measurement -------------------------------------------------------------------

Metric = tuple[str, float, str, float | None, str]


@dataclass
class Measurement:
    """Judged metrics and time series of one scenario."""

    scenario: Scenario
    metrics: list[Metric]
    series: dict[str, np.ndarray] = field(default_factory=dict)

    @property
    def passed(self) -> bool:
        """Every judged metric within its target."""
        return all(t is None or (np.isfinite(v) and abs(v) <= t)
                   for _, v, _, t, _ in self.metrics)


def _wrap(angle: np.ndarray) -> np.ndarray:
    return np.angle(np.exp(1j * np.asarray(angle)))


def measure(s: Scenario, params: Any = None) -> Measurement:
    """Run ``s`` through MuJoCo and the analytic model; judge the differences.

    Settles ``s.settle`` seconds at rest, schedules the open-loop controls and analytic
    states (:func:`wmr_mujoco.validation.schedule`), steps MuJoCo through them, and after
    every step reads the chassis pose and the lateral slip speed of every conventional
    wheel (its contact point's velocity along its axle,
    :func:`wmr_mujoco.validation.lateral_slip`).

    Raises:
        ValueError: unknown robot.
        SimulationDivergedError: the run diverged (never returned as a result).
    """
    model = load(s.robot, params)
    adapter = make_adapter(s.robot, params)
    set_actuation_mode(model, adapter.mode)
    data = mujoco.MjData(model)
    dt = model.opt.timestep
    for _ in range(round(s.settle / dt)):
        mujoco.mj_step(model, data)
    check_healthy(model, data)
    nstep = round(s.duration / dt)
    inputs, controls, analytic = schedule(s, adapter, adapter.sim_state(model, data), dt, nstep)
    sim = np.empty((nstep + 1, 3))
    sim[0] = chassis_pose(data)
    slip = np.zeros((nstep, len(adapter.lateral_wheels)))

    def on_step(k: int) -> None:
        # After mj_step the contacts belong to the step's start and qvel to its end: the
        # velocities the constraints produced at those contacts.
        slip[k] = lateral_slip(model, data, adapter.lateral_wheels)
        sim[k + 1] = chassis_pose(data)

    simulate(model, data, controls, engine="loop", on_step=on_step)
    t = dt * np.arange(nstep + 1)
    err = np.linalg.norm(sim[:, :2] - analytic[:, :2], axis=1)
    heading = np.degrees(_wrap(sim[:, 2] - analytic[:, 2]))
    speeds = np.array([np.mean(np.abs(adapter.wheel_speeds(u, x)))
                       for u, x in zip(inputs, analytic[:-1], strict=True)])
    path = float(np.sum(speeds) * dt)
    pct = 100.0 / path
    m: list[Metric] = [
        ("final position error", pct * err[-1], "% of path", POSITION_PCT, REQUIREMENT),
        ("worst position error over the run", pct * float(err.max()), "% of path",
         POSITION_PCT, REQUIREMENT),
        ("RMS position error", float(np.sqrt(np.mean(err**2))), "m", None, "reported"),
        ("final heading error", float(heading[-1]), "deg", None, "reported"),
        ("worst heading error over the run", float(np.abs(heading).max()), "deg", None,
         "reported"),
        ("path", path, "m", None, "mean distance rolled by the driven wheels"),
    ]
    for i, wheel in enumerate(adapter.lateral_wheels):
        m.append((f"lateral slip RMS, {wheel}", float(np.sqrt(np.mean(slip[:, i] ** 2))),
                  "m/s", LATERAL_SLIP_RMS, REQUIREMENT))
        m.append((f"lateral slip worst, {wheel}", float(np.abs(slip[:, i]).max()), "m/s",
                  None, "reported"))
    series = {"time": t, "sim": sim, "analytic": analytic, "slip": slip, "inputs": inputs}
    return Measurement(s, m, series)


def table(measurements: list[Measurement]) -> str:
    """Markdown table of every metric."""
    rows = ["| robot | scenario | metric | value | unit | target | basis |",
            "|---|---|---|---|---|---|---|"]
    for meas in measurements:
        for name, value, unit, target, basis in meas.metrics:
            tgt = "" if target is None else f"≤ {target:g}"
            rows.append(f"| {meas.scenario.robot} | {meas.scenario.name} | {name} | "
                        f"{value:.4g} | {unit} | {tgt} | {basis} |")
    return "\n".join(rows)


if __name__ == "__main__":
    import sys

    robots = sys.argv[1:] or list(ROBOTS)
    print(table([measure(s) for r in robots for s in scenarios_for(r)]))
