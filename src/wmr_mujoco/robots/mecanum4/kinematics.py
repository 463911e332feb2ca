"""``mecanum4`` on rate inputs: the step model, the kinematic model and the ideal one.

Inputs ``(u, v, r)``: the commanded body twist, driven as wheel rates from Lynch & Park's
ideal formula ``θ̇ = H(γ) ν_cmd`` (FL, FR, RL, RR). The **kinematic** model
``(Ẋ, Ẏ, ψ̇) = Rot(ψ) ν̄(ν_cmd)`` rolls on the model's own roller colliders
(:mod:`wmr_mujoco.robots.mecanum4.collider`: their contact's rolling rows, least squares
over the four wheels, averaged over the roller pitch; it contains the pitch average of
:mod:`wmr_mujoco.robots.roller_wheels.pitch_averaged`, ``tan γ̄ = ⟨sec φ⟩ tan γ``) and judges
the ramped
runs, with the **ideal** model ``Rot(ψ) ν_cmd`` beside it. A **step** command is judged
against the stick–slip dynamic model (:mod:`wmr_mujoco.robots.roller_wheels.roller_stick_slip`,
parameters from the compiled model by :mod:`.traction`): its body twist ``ν(t)`` from rest
is computed once, and the pose follows ``Rot(ψ) ν(t)``; the kinematic and ideal models
are reported beside it (:func:`judge_kinematic`). After the rise the step model rolls as
the kinematic model (its rows are the colliders' effective layout).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import ClassVar

import mujoco
import numpy as np

from wmr_mujoco.analytic.planar import twist_step, twist_steps, wrap_angle
from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.robots.mecanum4 import collider, step_batch, traction
from wmr_mujoco.robots.mecanum4.builder import WHEEL_NAMES
from wmr_mujoco.robots.mecanum4.geometry import layout as wheel_layout
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.roller_stick_slip import StepResponse, step_response
from wmr_mujoco.validation.adapters import POSE_UNITS, base_pose, per_distinct_row
from wmr_mujoco.validation.metrics import Metric, Target, Trace, pose_tracking, rms
from wmr_mujoco.validation.scenarios import Scenario

#: Names of the kinematic model's pose in a step run's analytic state.
KINEMATIC_STATE = ("x (kinematic)", "y (kinematic)", "heading (kinematic)")
#: Names of the ideal model's pose components in the analytic state.
IDEAL_STATE = ("x (ideal)", "y (ideal)", "heading (ideal)")
#: A step run's clock: time since the command, s (the step model's ``ν(t)`` is read at it).
CLOCK = "t"


@dataclass(frozen=True)
class MecanumKinematics:
    """Ramped runs: ``x = (X, Y, ψ)`` kinematic, then ideal. Steps: step model first.

    A step run's state is ``(X, Y, ψ)`` of the step model, of the kinematic model
    and of the ideal model, then the clock ``t``.

    Attributes:
        params: the robot's parameters (layout, roller count).
        step: for a step command, the step model's response from rest; None for a ramp.
        start_time: the simulation time at which the command starts, s (the settle).
    """

    #: ``sim_state`` reads the pose and joint positions alone (the runner's frames only).
    frames_only: ClassVar[bool] = True

    params: MecanumParams
    step: StepResponse | None = None
    start_time: float = 0.0
    mode: ActuationMode = ActuationMode.RATE
    wheel_joints: tuple[str, ...] = WHEEL_NAMES
    lateral_wheels: tuple[str, ...] = ()

    @property
    def state_names(self) -> tuple[str, ...]:
        """Pose of the judged model first (module docstring)."""
        if self.step is None:
            return ("x", "y", "heading", *IDEAL_STATE)
        return ("x", "y", "heading", *KINEMATIC_STATE, *IDEAL_STATE, CLOCK)

    @property
    def state_units(self) -> tuple[str, ...]:
        """Units of :attr:`state_names`."""
        if self.step is None:
            return (*POSE_UNITS, *POSE_UNITS)
        return (*POSE_UNITS, *POSE_UNITS, *POSE_UNITS, "s")

    @functools.cached_property
    def layout(self) -> ok.WheelLayout:
        """Ideal wheel layout (the roller probes' slide speeds use it)."""
        return wheel_layout(self.params)

    @functools.cached_property
    def jacobian(self) -> np.ndarray:
        """Ideal ``H(γ)`` with ``θ̇ = H ν``."""
        return ok.wheel_jacobian(self.layout)

    def realised(self, u: np.ndarray) -> tuple[float, float, float]:
        """``ν̄``: the colliders' mean twist under the ideal wheel rates ``H(γ) u``.

        :func:`~wmr_mujoco.robots.mecanum4.collider.realised_twist`: the rolling rows of
        the model's own roller colliders, least squares over the four wheels, averaged
        over the roller pitch.
        """
        return _realised(self.params, float(u[0]), float(u[1]), float(u[2]))

    def twist(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """The commanded body twist (inputs are body rates)."""
        return np.asarray(u, float)

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Wheel rates ``θ̇ = H(γ) u``."""
        return self.jacobian @ np.asarray(u, float)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """``(Rot(ψ) S u, Rot(ψ_ideal) u)``; a step run: ``Rot(ψ) ν(t)`` before them, ṫ = 1."""
        nu = np.asarray(u, float)
        poses = [self.realised(nu), nu]
        if self.step is not None:
            poses.insert(0, self.step.twist_at(float(x[-1])))
        out = []
        for i, (tu, tv, tr) in enumerate(poses):
            c, s = math.cos(x[3 * i + 2]), math.sin(x[3 * i + 2])
            out += [c * tu - s * tv, s * tu + c * tv, tr]
        if self.step is not None:
            out.append(1.0)
        return np.array(out)

    @property
    def exact_step(self) -> Callable[[np.ndarray, np.ndarray, float], np.ndarray] | None:
        """A ramped run's exact step under a held input (None: a step run, RK4).

        Both poses follow a constant body twist over the step (``ν̄(u)`` and ``u``):
        :func:`~wmr_mujoco.analytic.planar.twist_step`, the arc RK4 on :meth:`rhs`
        approximates (its error per step ``|ν| r⁴ Δt⁵ / 2880``, below round-off here). A
        step run's ``ν(t)`` changes within the step.
        """
        return self._arcs if self.step is None else None

    def _arcs(self, x: np.ndarray, u: np.ndarray, dt: float) -> np.ndarray:
        nu = np.asarray(u, float)
        return np.concatenate([twist_step(x[:3], self.realised(nu), dt),
                               twist_step(x[3:6], nu, dt)])

    def trajectory(self, x0: np.ndarray, inputs: np.ndarray, dt: float) -> np.ndarray:
        """Every step's state at once: the floats of :attr:`exact_step` or RK4 on :meth:`rhs`.

        A ramped run: :func:`~wmr_mujoco.analytic.planar.twist_steps` of ``ν̄(u_k)`` and
        ``u_k``. A step run: the RK4 step of :meth:`rhs` written out over all steps. Its
        right-hand side does not depend on the positions, and the headings and the clock
        only on the clock, so every stage is elementwise arithmetic on the stage clocks
        ``t``, ``t + Δt/2``, ``t + Δt/2``, ``t + Δt``, and each state the running sum
        ``x_k + Δt/6 (k₁ + 2k₂ + 2k₃ + k₄)`` (one sequential ``np.cumsum``).

        Returns:
            (N + 1, n) states, ``x0`` first.
        """
        x0 = np.asarray(x0, float)
        nu = np.asarray(inputs, float).reshape(-1, 3)
        realised = self._realised_rows(nu)
        if self.step is None:
            return np.concatenate([twist_steps(x0[:3], realised, dt),
                                   twist_steps(x0[3:6], nu, dt)], axis=1)
        n = len(nu)
        h = dt / 6.0
        ones = np.ones(n)
        clock = np.cumsum(np.concatenate([[x0[-1]], h * (ones + 2.0 * ones + 2.0 * ones
                                                         + ones)]))
        stages = (clock[:-1], clock[:-1] + 0.5 * dt * ones, clock[:-1] + 0.5 * dt * ones,
                  clock[:-1] + dt * ones)
        step_twists = [np.stack([np.interp(t, self.step.time, self.step.twist[:, j])
                                 for j in range(3)], axis=1) for t in stages]
        out = np.empty((n + 1, len(x0)))
        out[:, -1] = clock
        for i, twists in enumerate((step_twists, [realised] * 4, [nu] * 4)):
            rates = [tw[:, 2] for tw in twists]
            heading = np.cumsum(np.concatenate([[x0[3 * i + 2]], h * (
                rates[0] + 2.0 * rates[1] + 2.0 * rates[2] + rates[3])]))
            psi = heading[:-1]
            stage_psi = (psi, psi + 0.5 * dt * rates[0], psi + 0.5 * dt * rates[1],
                         psi + dt * rates[2])
            for j in range(2):
                k = []
                for ps, tw in zip(stage_psi, twists, strict=True):
                    c, sn = np.cos(ps), np.sin(ps)
                    k.append(c * tw[:, 0] - sn * tw[:, 1] if j == 0
                             else sn * tw[:, 0] + c * tw[:, 1])
                out[:, 3 * i + j] = np.cumsum(np.concatenate(
                    [[x0[3 * i + j]], h * (k[0] + 2.0 * k[1] + 2.0 * k[2] + k[3])]))
            out[:, 3 * i + 2] = heading
        return out

    def _realised_rows(self, nu: np.ndarray) -> np.ndarray:
        """(N, 3) :meth:`realised` of each row of ``nu``, once per distinct row."""
        return per_distinct_row(self.realised, nu, 3)

    def controls_on(self, inputs: np.ndarray, states: np.ndarray) -> np.ndarray:
        """(N, 4) :meth:`controls` of every step, once per distinct input (they read no state)."""
        return per_distinct_row(lambda u: self.controls(u, None), inputs, self.jacobian.shape[0])

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """The ``base`` site's pose, once for each model (and the clock of a step run)."""
        pose = base_pose(model, data)
        if self.step is None:
            return np.concatenate([pose, pose])
        return np.concatenate([pose, pose, pose, [data.time - self.start_time]])


@functools.lru_cache(maxsize=4096)
def _realised(params: MecanumParams, u: float, v: float, r: float
              ) -> tuple[float, float, float]:
    """Cached ``ν̄`` for one commanded twist (a run has few distinct inputs)."""
    su, sv, sr = collider.realised_twist(params, np.array([u, v, r]))
    return float(su), float(sv), float(sr)


def is_step(scenario: Scenario) -> bool:
    """Whether the command starts at full value (a step) rather than from rest."""
    return bool(np.any(scenario.input_at(0.0) != 0.0))


def kinematic_adapter(scenario: Scenario, model: mujoco.MjModel,
                      params: RobotParams | None) -> MecanumKinematics:
    """The kinematic models; a step command also gets the step model's response.

    Raises:
        ValueError: a step command that changes during the run (the step model holds
            the command of t = 0).
    """
    p = params_or_default(params, MecanumParams)
    if not is_step(scenario):
        return MecanumKinematics(p)
    twist = scenario.input_at(0.0)
    if not np.array_equal(scenario.input_at(scenario.duration), twist):
        raise ValueError(f"{scenario.key}: a step command must be held over the run "
                         f"(u(0) = {twist}, u(end) = {scenario.input_at(scenario.duration)})")
    response = step_batch.take(twist, scenario.duration, params)  # prepared with others
    if response is None:
        platform, command = traction.step_platform(model, p, twist)
        response = step_response(platform, command, scenario.duration)
    return MecanumKinematics(p, response, scenario.settle)


def _reported(scenario: Scenario, trace: Trace, adapter: MecanumKinematics,
              columns: slice, label: str, note: str) -> list[Metric]:
    """Worst and RMS errors against the model whose pose is in ``columns``, reported."""
    sub = Trace(time=trace.time, sim=[s[:3] for s in trace.sim],
                analytic=[a[columns] for a in trace.analytic],
                state_names=trace.state_names[:3], state_units=trace.state_units[:3])
    out = []
    for m in pose_tracking(scenario, sub, adapter, {}):
        if (m.name, m.unit) in (("worst position error", "% of path"),
                                ("worst centre drift", "m"), ("RMS position error", "m"),
                                ("worst heading error", "deg")):
            out.append(Metric(f"{m.name}, {label}", m.value, m.unit, note=note))
    out.append(Metric(f"RMS heading error, {label}", heading_rms(sub), "deg", note=note))
    return out


def heading_rms(trace: Trace) -> float:
    """RMS over the run of the wrapped heading error, degrees."""
    tr = trace.arrays()
    return rms(np.degrees(wrap_angle(tr["sim"][:, 2] - tr["analytic"][:, 2])))


def judge_kinematic(scenario: Scenario, trace: Trace, adapter: MecanumKinematics,
                    targets: Mapping[str, Target]) -> list[Metric]:
    """Pose tracking against the judged model; the other models' errors beside it.

    Worst, RMS and final errors over the whole run
    (:func:`~wmr_mujoco.validation.metrics.pose_tracking`) and the RMS heading error,
    judged at the requirement: a ramped run against the kinematic model (the colliders'),
    a step run against the step model. Reported, not judged: for a step run the kinematic
    model's worst and RMS errors, and for every run the ideal Lynch & Park model's.
    """
    metrics = pose_tracking(scenario, trace, adapter, targets)
    metrics.append(Metric("RMS heading error", heading_rms(trace), "deg"))
    ideal = slice(3, 6) if adapter.step is None else slice(6, 9)
    if adapter.step is not None:
        metrics += _reported(scenario, trace, adapter, slice(3, 6), "kinematic model",
                             "reported: the colliders' kinematics (instant step)")
    metrics += _reported(scenario, trace, adapter, ideal, "ideal model",
                         "reported: Lynch & Park with horizontal contact rollers (no "
                         "pitch averaging)")
    return metrics
