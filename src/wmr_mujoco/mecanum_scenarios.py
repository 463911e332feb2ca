"""Open-loop scenarios of ``mecanum4`` against Lynch & Park's kinematics, judged over the run.

A scenario is data: a body twist ``ν = (u, v, r)`` reached by a linear ramp (or a step),
held to the end. The wheels get ``θ̇ = H ν`` from the ideal formula
(:func:`wmr_mujoco.analytic.omni_kinematics.wheel_jacobian` with the mecanum layout); the
same twist is integrated analytically, ``(Ẋ, Ẏ, ψ̇) = (Rot(ψ)(u, v), r)``. Judged over the
whole run (worst, RMS and final): position error as % of the run's analytic path, heading
error in degrees. Targets (issue 15, requirements): 1 % of path and 1°.

Derived bound beside the requirement (docs/mecanum.md §3): on its rollers a wheel carries
the chassis sideways at ``cos φ`` of the ideal speed, φ the wheel angle from the roller's
middle, so a sideways run falls short by ``1 − sin(π/n)/(π/n)`` of its lateral path
(0.64 % for n = 16 rollers).

:func:`judge` returns rows ``(metric, value, unit, target, basis)``; :class:`MecanumKinematics`
follows :class:`wmr_mujoco.adapters.Adapter`, so the validation runner can take it as is.
"""

from __future__ import annotations

import functools
import time
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.adapters import base_pose
from wmr_mujoco.analytic import mecanum_roller as mr
from wmr_mujoco.analytic import omni_kinematics as ok
from wmr_mujoco.analytic.integrate import integrate
from wmr_mujoco.builders.mecanum4 import WHEEL_NAMES
from wmr_mujoco.params_mecanum import MecanumParams
from wmr_mujoco.scenarios import OMNI_DIRECTIONS_DEG, OMNI_SPEED, OMNI_YAW_RATE, Scenario
from wmr_mujoco.signals import const
from wmr_mujoco.simulation import check_healthy

#: Requirements (issue 15): position error in % of path and heading error in degrees.
POSITION_PCT = 1.0
HEADING_DEG = 1.0
#: Requirement (issue 15) on the rolling-radius ripple, %, and the real-time factor.
RIPPLE_PCT = 0.3
REAL_TIME_FACTOR = 50.0

Row = tuple[str, float, str, float, str]


def layout(params: MecanumParams) -> ok.WheelLayout:
    """The ideal layout of the model's wheels, in :data:`WHEEL_NAMES` order (FL, FR, RL, RR)."""
    lay = ok.mecanum_layout(params.wheel_radius, params.half_length, params.half_track)
    if not np.isclose(params.roller_angle, np.pi / 4.0):
        lay = ok.WheelLayout(lay.positions, lay.drive_angles,
                             np.sign(lay.roller_angles) * params.roller_angle, lay.radii)
    return lay


@dataclass(frozen=True)
class MecanumScenario:
    """A body twist held for ``duration`` seconds after a ramp (``ramp = 0``: a step).

    Attributes:
        name: label.
        twist: ``(u, v, r)`` body-frame target, m/s and rad/s.
        duration: seconds from the start of the command to the end.
        ramp: seconds of the linear ramp from rest; 0 for a step command.
        settle: seconds at rest before the command.
    """

    name: str
    twist: tuple[float, float, float]
    duration: float = 4.0
    ramp: float = 0.5
    settle: float = 0.5

    def __post_init__(self) -> None:
        if not 0.0 < self.duration <= 60.0:
            raise ValueError(f"duration = {self.duration!r} s; valid range is (0, 60]")
        if not 0.0 <= self.ramp < self.duration:
            raise ValueError(f"ramp = {self.ramp!r} s; valid range is [0, duration)")
        if not 0.0 <= self.settle <= 5.0:
            raise ValueError(f"settle = {self.settle!r} s; valid range is [0, 5]")
        if len(self.twist) != 3 or not np.all(np.isfinite(self.twist)):
            raise ValueError(f"twist = {self.twist!r}; must be three finite numbers (u, v, r)")

    def twist_at(self, t: float) -> np.ndarray:
        """Commanded twist ``t`` seconds after the start of the command."""
        scale = 1.0 if self.ramp == 0.0 else float(np.clip(t / self.ramp, 0.0, 1.0))
        return np.asarray(self.twist, float) * scale


def standard_scenarios(duration: float = 4.0, speed: float = OMNI_SPEED,
                       yaw_rate: float = OMNI_YAW_RATE) -> list[MecanumScenario]:
    """8 translations, rotation and two translation+rotation mixes; 0.5 s ramps, then steps.

    The manoeuvres are the omni robot's (:mod:`wmr_mujoco.scenarios`).
    """
    out = []
    for ramp, tag in ((0.5, "ramp"), (0.0, "step")):
        out += [MecanumScenario(f"translate {deg}° ({tag})",
                                (speed * np.cos(np.radians(deg)),
                                 speed * np.sin(np.radians(deg)), 0.0), duration, ramp)
                for deg in OMNI_DIRECTIONS_DEG]
        out.append(MecanumScenario(f"rotate ({tag})", (0.0, 0.0, yaw_rate), duration, ramp))
        out.append(MecanumScenario(f"translate+rotate ({tag})", (speed, 0.0, 0.5 * yaw_rate),
                                   duration, ramp))
        out.append(MecanumScenario(f"diagonal+rotate ({tag})",
                                   (-0.6 * speed, 0.6 * speed, -yaw_rate), duration, ramp))
    return out


def runner_scenarios(duration: float = 4.0) -> list[Scenario]:
    """The standard scenarios as the validation runner's :class:`Scenario` objects.

    Robot ``"mecanum4"``, inputs ``(u, v, r)`` as ramped or stepped constants, ready for
    ``wmr_mujoco.scenarios.SCENARIOS``.
    """
    return [Scenario("mecanum4", s.name, tuple(const(float(x), s.ramp) for x in s.twist),
                     duration=s.duration, settle=s.settle)
            for s in standard_scenarios(duration)]


@dataclass(frozen=True)
class ScenarioResult:
    """Series of one run (one row per step after the settle, the start included).

    Attributes:
        name: scenario label.
        time: (K+1,) s from the start of the command.
        sim: (K+1, 3) simulated ``(x, y, heading)`` of the ``base`` site.
        analytic: (K+1, 3) integrated ideal kinematics from the same start.
        wall: seconds of wall-clock time spent in ``mj_step`` during the command.
    """

    name: str
    time: np.ndarray
    sim: np.ndarray
    analytic: np.ndarray
    wall: float

    @property
    def path(self) -> float:
        """Analytic path length of the base origin, m."""
        return float(np.sum(np.linalg.norm(np.diff(self.analytic[:, :2], axis=0), axis=1)))

    @property
    def position_error(self) -> np.ndarray:
        """(K+1,) distance between simulated and analytic base origin, m."""
        return np.linalg.norm(self.sim[:, :2] - self.analytic[:, :2], axis=1)

    @property
    def heading_error(self) -> np.ndarray:
        """(K+1,) simulated minus analytic heading, wrapped, degrees."""
        return np.degrees(np.angle(np.exp(1j * (self.sim[:, 2] - self.analytic[:, 2]))))

    @property
    def real_time_factor(self) -> float:
        """Simulated seconds per wall-clock second of ``mj_step``."""
        return float(self.time[-1] / self.wall) if self.wall > 0 else float("nan")


def _layout_matches(model: mujoco.MjModel, lay: ok.WheelLayout) -> None:
    """Check the model has the four wheel hinges with one actuator each, FL FR RL RR."""
    for name in WHEEL_NAMES:
        if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_ACTUATOR, name) < 0:
            raise ValueError(f"model has no actuator {name!r}; is it mecanum4?")
    if model.nu != lay.n:
        raise ValueError(f"model has {model.nu} actuators; mecanum4 has {lay.n}")


def run_scenario(model: mujoco.MjModel, params: MecanumParams,
                 scenario: MecanumScenario) -> ScenarioResult:
    """Run ``scenario`` open loop on ``model`` (built from ``params``) and analytically.

    Raises:
        ValueError: the model is not a mecanum4 model.
        SimulationDivergedError: NaN or MuJoCo warnings in the run.
    """
    lay = layout(params)
    _layout_matches(model, lay)
    H = ok.wheel_jacobian(lay)
    acts = np.array([model.actuator(n).id for n in WHEEL_NAMES])
    data = mujoco.MjData(model)
    dt = model.opt.timestep
    for _ in range(round(scenario.settle / dt)):
        mujoco.mj_step(model, data)
    check_healthy(model, data)
    nstep = round(scenario.duration / dt)
    twists = np.array([scenario.twist_at(k * dt) for k in range(nstep)])
    sim = np.empty((nstep + 1, 3))
    sim[0] = base_pose(model, data)
    wall = 0.0
    for k in range(nstep):
        data.ctrl[acts] = H @ twists[k]
        t0 = time.perf_counter()
        mujoco.mj_step(model, data)
        wall += time.perf_counter() - t0
        sim[k + 1] = base_pose(model, data)
        if k % 250 == 0:
            check_healthy(model, data)
    check_healthy(model, data)
    analytic = integrate(lambda x, nu: ok.body_to_world(x[2], nu), sim[0], twists, dt)
    sim[:, 2] = sim[0, 2] + np.unwrap(sim[:, 2] - sim[0, 2])
    return ScenarioResult(scenario.name, dt * np.arange(nstep + 1), sim, analytic, wall)


def step_lag_floor_pct(params: MecanumParams, scenario: MecanumScenario,
                       path: float) -> float:
    """Least position lag of a step translation, % of ``path`` (docs/mecanum.md §4).

    Each wheel pushes the chassis only along its contact roller's axis ``e_i``, by at most
    ``μ N_i = μ m g / 4``; the components across the motion cancel in this symmetric
    layout, so along the unit direction ``ê`` the chassis accelerates at most at
    ``a = (μ g / 4) Σ |e_i · ê|`` and falls behind a step to speed V by ``V² / (2a)``.
    NaN for runs that turn (the bound is for pure translation) or with no path.
    """
    u, v, r = scenario.twist
    speed = float(np.hypot(u, v))
    if r != 0.0 or speed == 0.0 or path <= 0.0:
        return float("nan")
    lay = layout(params)
    e = np.stack([np.cos(lay.roller_angles), np.sin(lay.roller_angles)], axis=1)
    accel = params.sim.friction * 9.81 / 4.0 * float(np.abs(e @ (np.array([u, v]) / speed)).sum())
    return 100.0 * speed**2 / (2.0 * accel) / path


def judge(result: ScenarioResult, params: MecanumParams | None = None,
          scenario: MecanumScenario | None = None) -> list[Row]:
    """Judged rows ``(metric, value, unit, target, basis)`` of one run.

    Position error in % of the run's analytic path (worst over the run, RMS over the run,
    final); for a run with under 1 cm of path (pure rotation) the drift in mm is reported
    instead, without target. Heading error in degrees, worst, RMS and final. Given the
    ``params`` and a step ``scenario`` that translates, a last row reports the derived
    friction floor of the lag (:func:`step_lag_floor_pct`).
    """
    req = "requirement (issue 15)"
    rows: list[Row] = []
    e, h = result.position_error, result.heading_error
    path = result.path
    if path >= 0.01:
        pct = 100.0 * e / path
        rows += [("position error, worst over run", float(pct.max()), "% of path",
                  POSITION_PCT, req),
                 ("position error, RMS over run", float(np.sqrt(np.mean(pct**2))),
                  "% of path", POSITION_PCT, req),
                 ("position error, final", float(pct[-1]), "% of path", POSITION_PCT, req)]
    else:
        rows.append(("position drift, worst over run", 1000.0 * float(e.max()), "mm",
                     float("nan"), "reported (no path to scale by)"))
    rows += [("heading error, worst over run", float(np.abs(h).max()), "deg", HEADING_DEG, req),
             ("heading error, RMS over run", float(np.sqrt(np.mean(h**2))), "deg",
              HEADING_DEG, req),
             ("heading error, final", float(abs(h[-1])), "deg", HEADING_DEG, req)]
    if params is not None and scenario is not None and scenario.ramp == 0.0:
        floor = step_lag_floor_pct(params, scenario, path)
        if np.isfinite(floor):
            rows.append(("position lag floor of a step (friction)", floor, "% of path",
                         float("nan"), "derived bound: V²/(2a), a = (μg/4) Σ|e_i·ê|"))
    return rows


def lateral_bound_pct(params: MecanumParams) -> float:
    """Derived lateral shortfall of a sideways run, ``100 (1 − sin(π/n)/(π/n))`` %."""
    return 100.0 * (1.0 - mr.mean_lateral_factor(np.pi / params.rollers_per_wheel))


def run_all(model: mujoco.MjModel, params: MecanumParams,
            scenarios: Sequence[MecanumScenario]) -> list[tuple[ScenarioResult, list[Row]]]:
    """Run and judge every scenario."""
    out = []
    for s in scenarios:
        res = run_scenario(model, params, s)
        out.append((res, judge(res, params, s)))
    return out


@dataclass(frozen=True)
class MecanumKinematics:
    """Adapter for the validation runner: ``x = (X, Y, ψ)``; controls ``θ̇ = H ν``.

    Inputs ``(u, v, r)`` in the body frame, as the omni robot's.
    """

    params: MecanumParams = MecanumParams()  # noqa: RUF009 (frozen, immutable)
    robot: str = "mecanum4"
    mode: str = "rate"
    state_names: tuple[str, ...] = ("x", "y", "heading")
    wheel_joints: tuple[str, ...] = WHEEL_NAMES
    lateral_wheels: tuple[str, ...] = ()

    @functools.cached_property
    def jacobian(self) -> np.ndarray:
        """``H`` with ``θ̇ = H ν``."""
        return ok.wheel_jacobian(layout(self.params))

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Wheel rates ``H u`` (FL, FR, RL, RR)."""
        return self.jacobian @ np.asarray(u, float)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """``(Rot(ψ)(u, v), r)``."""
        return ok.body_to_world(x[2], u)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """``(x, y, heading)`` of the ``base`` site."""
        return base_pose(model, data)
