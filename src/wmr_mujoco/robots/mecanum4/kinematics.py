"""``mecanum4`` on rate inputs: the ideal and the roller-pitch-averaged kinematics.

Inputs ``(u, v, r)``: the commanded body twist, driven as wheel rates from Lynch & Park's
ideal formula ``θ̇ = H(γ) ν_cmd`` (FL, FR, RL, RR). The analytic state carries two poses
side by side from the same start: the **pitch-averaged** model's ``(x, y, heading)``,
``(Ẋ, Ẏ, ψ̇) = Rot(ψ) S ν_cmd`` with ``S = H(γ̄)⁺ H(γ)``
(:mod:`wmr_mujoco.analytic.pitch_averaged`: the rolling constraint averaged over one
roller pitch, ``tan γ̄ = ⟨sec φ⟩ tan γ``), and the **ideal** model's, ``Rot(ψ) ν_cmd``. The
judged model is the first; the second is reported beside it so that the effect of the
discrete rollers shows (:func:`judge_kinematic`).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.analytic import omni_kinematics as ok
from wmr_mujoco.analytic import pitch_averaged as pa
from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.builders.mecanum4 import WHEEL_NAMES
from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.models.params_mecanum import MecanumParams
from wmr_mujoco.robots.mecanum4 import traction
from wmr_mujoco.robots.mecanum4.geometry import layout as wheel_layout
from wmr_mujoco.validation import metrics as mt
from wmr_mujoco.validation.adapters import POSE_UNITS, base_pose
from wmr_mujoco.validation.metrics import Metric, Target, Trace, pose_tracking
from wmr_mujoco.validation.scenarios import Scenario

#: Names of the ideal model's pose components in the analytic state.
IDEAL_STATE = ("x (ideal)", "y (ideal)", "heading (ideal)")


@dataclass(frozen=True)
class MecanumKinematics:
    """``x = (X, Y, ψ)`` of the pitch-averaged model, then of the ideal one.

    Attributes:
        params: the robot's parameters (layout, roller count).
        accel_time: for a step command, the traction-limited time ``T`` to reach it
            (:func:`wmr_mujoco.robots.mecanum4.traction.step_acceleration_time`); None
            for a ramped command.
        timestep: the model's Δt, s (the step's one-step delay).
    """

    params: MecanumParams
    accel_time: float | None = None
    timestep: float = 0.0
    mode: ActuationMode = ActuationMode.RATE
    state_names: tuple[str, ...] = ("x", "y", "heading", *IDEAL_STATE)
    state_units: tuple[str, ...] = (*POSE_UNITS, *POSE_UNITS)
    wheel_joints: tuple[str, ...] = WHEEL_NAMES
    lateral_wheels: tuple[str, ...] = ()

    @functools.cached_property
    def layout(self) -> ok.WheelLayout:
        """Ideal wheel layout (the roller probes' slide speeds use it)."""
        return wheel_layout(self.params)

    @functools.cached_property
    def jacobian(self) -> np.ndarray:
        """Ideal ``H(γ)`` with ``θ̇ = H ν``."""
        return ok.wheel_jacobian(self.layout)

    def realised(self, u: np.ndarray) -> tuple[float, float, float]:
        """``S ν``: the pitch-averaged twist under the ideal wheel rates ``H(γ) u``.

        ``S = H(γ̄)⁺ H(γ)`` with γ̄ on the wheels that turn (rate above 1e-9 rad/s).
        """
        return _realised(self.layout_key, float(u[0]), float(u[1]), float(u[2]))

    @functools.cached_property
    def layout_key(self) -> tuple[tuple[float, ...], int]:
        """Hashable layout (positions, drive and roller angles, radii) and roller count."""
        lay = self.layout
        return (tuple(np.concatenate([lay.positions.ravel(), lay.drive_angles,
                                      lay.roller_angles, lay.radii]).tolist()),
                self.params.rollers_per_wheel)

    def twist(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """The commanded body twist (inputs are body rates)."""
        return np.asarray(u, float)

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Wheel rates ``θ̇ = H(γ) u``."""
        return self.jacobian @ np.asarray(u, float)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """``(Rot(ψ) S u, Rot(ψ_ideal) u)``."""
        nu = np.asarray(u, float)
        su, sv, sr = self.realised(nu)
        c, s = math.cos(x[2]), math.sin(x[2])
        ci, si = math.cos(x[5]), math.sin(x[5])
        return np.array([c * su - s * sv, s * su + c * sv, sr,
                         ci * nu[0] - si * nu[1], si * nu[0] + ci * nu[1], nu[2]])

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """The ``base`` site's pose, once for each model."""
        pose = base_pose(model, data)
        return np.concatenate([pose, pose])


@functools.lru_cache(maxsize=4096)
def _realised(key: tuple[tuple[float, ...], int], u: float, v: float, r: float
              ) -> tuple[float, float, float]:
    """Cached ``S ν`` for one commanded twist (a run has few distinct inputs)."""
    nu = np.array([u, v, r])
    turning = tuple(bool(abs(w) > 1e-9) for w in _jacobian(key) @ nu)
    su, sv, sr = _twist_map(key, turning) @ nu
    return float(su), float(sv), float(sr)


def _layout_of(key: tuple[tuple[float, ...], int]) -> ok.WheelLayout:
    flat, _ = key
    n = len(flat) // 5
    v = np.asarray(flat)
    return ok.WheelLayout(v[:2 * n].reshape(n, 2), v[2 * n:3 * n], v[3 * n:4 * n], v[4 * n:])


@functools.lru_cache(maxsize=16)
def _jacobian(key: tuple[tuple[float, ...], int]) -> np.ndarray:
    return ok.wheel_jacobian(_layout_of(key))


@functools.lru_cache(maxsize=64)
def _twist_map(key: tuple[tuple[float, ...], int], turning: tuple[bool, ...]) -> np.ndarray:
    """Cached :func:`~wmr_mujoco.analytic.pitch_averaged.realised_twist_map`."""
    return pa.realised_twist_map(_layout_of(key), key[1], np.asarray(turning))


def is_step(scenario: Scenario) -> bool:
    """Whether the command starts at full value (a step) rather than from rest."""
    return bool(np.any(scenario.input_at(0.0) != 0.0))


def kinematic_adapter(scenario: Scenario, model: mujoco.MjModel,
                      params: RobotParams | None) -> MecanumKinematics:
    """The kinematic models; a step command also gets its traction-limited rise time."""
    p = params_or_default(params, MecanumParams)
    accel = None
    if is_step(scenario):
        accel = traction.step_acceleration_time(model, p, scenario.input_at(0.0))
    return MecanumKinematics(p, accel, float(model.opt.timestep))


def step_targets(scenario: Scenario, adapter: MecanumKinematics, path: float,
                 targets: Mapping[str, Target]) -> dict[str, Target]:
    """The targets of a run: for a step command, the requirement plus the step's lag.

    A step is followed no faster than traction allows (:mod:`.traction`): the chassis
    reaches the commanded twist after the rise time T, and starts one time step Δt late
    (the velocity servo turns the wheel in the step the command arrives; the rim drags
    the chassis through the contact from the next step on). It falls behind the instant
    step of the kinematics by ``ν (T/2 + Δt)`` for good: ``|(u, v)| (T/2 + Δt)`` in
    position and ``|r| (T/2 + Δt)`` in heading. The bound is the ramped runs'
    requirement plus that lag, in the same unit (% of this run's path, degrees).
    """
    out = dict(targets)
    if adapter.accel_time is None:
        return out
    t_rise = adapter.accel_time
    delay = t_rise / 2.0 + adapter.timestep
    u, v, r = scenario.input_at(0.0)
    lag_m = float(np.hypot(u, v)) * delay
    lag_deg = float(np.degrees(abs(r) * delay))
    basis = (f"traction-limited step (roller-axis forces ≤ μN): rise time T = "
             f"{1000 * t_rise:.1f} ms, lag ν (T/2 + Δt), Δt = "
             f"{1000 * adapter.timestep:g} ms")
    pos, head = targets.get(mt.POSITION_PCT), targets.get(mt.HEADING_DEG)
    if pos is not None and path > mt.MIN_PATH:
        lag_pct = 100.0 * lag_m / path
        out[mt.POSITION_PCT] = Target.derived(
            pos.value + lag_pct, f"{pos.value:g} % ({pos.basis}) + {basis} = "
                                 f"{1000 * lag_m:.2f} mm = {lag_pct:.3f} % of path")
    if head is not None:
        out[mt.HEADING_DEG] = Target.derived(
            head.value + lag_deg, f"{head.value:g}° ({head.basis}) + {basis} = "
                                  f"{lag_deg:.3f}°")
    return out


def judge_kinematic(scenario: Scenario, trace: Trace, adapter: MecanumKinematics,
                    targets: Mapping[str, Target]) -> list[Metric]:
    """Pose tracking against the pitch-averaged model; the ideal model's errors beside it.

    Worst, RMS and final errors over the whole run
    (:func:`~wmr_mujoco.validation.metrics.pose_tracking`), judged on the pitch-averaged
    model with :func:`step_targets`; the ideal Lynch & Park model's worst position
    (% of path) and heading errors are reported, not judged.
    """
    tr = trace.arrays()
    ana = tr["analytic"]
    path = float(np.sum(np.linalg.norm(np.diff(ana[:, :2], axis=0), axis=1)))
    metrics = pose_tracking(scenario, trace, adapter, step_targets(scenario, adapter, path,
                                                                   targets))
    ideal = Trace(time=trace.time, sim=[s[:3] for s in trace.sim],
                  analytic=[a[3:6] for a in trace.analytic],
                  state_names=trace.state_names[:3], state_units=trace.state_units[:3])
    for m in pose_tracking(scenario, ideal, adapter, {}):
        if (m.name, m.unit) in (("worst position error", "% of path"),
                                ("worst centre drift", "m"), ("worst heading error", "deg")):
            metrics.append(Metric(f"{m.name}, ideal model", m.value, m.unit,
                                  note="reported: Lynch & Park with horizontal contact "
                                       "rollers (no pitch averaging)"))
    return metrics
