"""omni3's traction limit: the torque at which a wheel starts to slip (issue 16).

Prediction (:func:`predicted_slip_torque`): at rest, torques ``τ = s · pattern`` give
rolling-wheel tractions ``F_t = (τ − I_w H ν̇)/r`` with ``ν̇ = (P + I_w HᵀH)⁻¹ Hᵀ τ``
(mean lever L) and normal loads N from the robot's balance
(:meth:`~wmr_mujoco.robots.roller_wheels.omni_hybrid.OmniHybrid.normal_loads`); both are affine in
s, so each wheel's onset solves ``s |F₁| = μ (N₀ + s N₁)``.

Measurement (:func:`measure_slip_onset`): ONE run in torque mode whose scale ramps
linearly, ``s(t) = s₀ + ṡ t``, from rest. The slip speed of wheel i,
``|r (θ̇_i − (H(σ) ν)_i)|``, is read from the physics at every step. Below the limit it
ripples (each roller hand-over jolts the contact, by up to ~1 cm/s); past it, it grows
for good. The reading is the scale from which the slip stays above ``v_th`` to the end
of the ramp. It lags the onset (derived): once the traction saturates at ``μ N`` the
excess torque ``ṡ (t − t*)`` spins the wheel up alone, ``I_w d(slip)/dt / r = ṡ (t −
t*)``, so the slip reaches ``v_th`` after ``Δt = √(2 I_w v_th / (r ṡ))``: the onset is the
reading minus ``ṡ Δt``, to within the sampling ``ṡ Δt_step`` (the stated resolution).

The prediction is quasi-static (at rest); during the ramp the robot speeds up and the
hand-overs modulate the loads, so the ramp is short (0.3 s): a slower ramp reaches the
onset at a higher speed (the measured onset moves by a few % between 0.3 and 0.5 s
ramps).
"""

from __future__ import annotations

import math

import numpy as np

from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.runs import WHEELS, base_states, hybrid, settled
from wmr_mujoco.robots.roller_wheels import omni_hybrid as oh
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.sim.engine import simulate
from wmr_mujoco.validation.metrics import Metric, Series, Target
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario

SLIP = Target.requirement(5.0, "accuracy asked of the traction model: slip-onset "
                                    "torque predicted within 5 %")
#: Torque pattern of the scenario (a push along x), scaled to a largest entry of 1.
PATTERN = (0.0, -1.0, 1.0)
#: Slip speed that counts as slipping for good, m/s.
SLIP_SPEED = 0.003
#: The ramp: from this fraction of the predicted onset to ``RAMP_END`` of it, in
#: ``RAMP_TIME`` seconds.
RAMP_START, RAMP_END, RAMP_TIME = 0.7, 1.3, 0.3


def traction_and_load(hy: oh.OmniHybrid, torques: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Traction ``F_t`` (N, along t_i) and normal loads ``N`` (N) under ``torques`` at rest."""
    H = ok.wheel_jacobian(ok.symmetric_layout(hy.radius, hy.distance))
    P = np.diag([hy.mass, hy.mass, hy.inertia[2, 2]])
    nudot = np.linalg.solve(P + hy.wheel_inertia * H.T @ H, H.T @ torques)
    thdd = H @ nudot
    force = (torques - hy.wheel_inertia * thdd) / hy.radius
    return force, hy.normal_loads(force, thdd)


def predicted_slip_torque(hy: oh.OmniHybrid, pattern: np.ndarray, friction: float) -> float:
    """Scale s of ``τ = s · pattern`` at which the first wheel reaches ``|F_t| = μ N``."""
    f1, n1_total = traction_and_load(hy, pattern)
    _, n0 = traction_and_load(hy, np.zeros(3))
    n1 = n1_total - n0
    onsets = [friction * n0[i] / (abs(f1[i]) - friction * n1[i])
              for i in range(3) if abs(f1[i]) - friction * n1[i] > 0]
    return min(onsets) if onsets else math.inf


def _pattern(pattern: tuple[float, float, float]) -> np.ndarray:
    pat = np.asarray(pattern, float)
    if pat.shape != (3,) or not np.all(np.isfinite(pat)) or not np.any(pat):
        raise ValueError(f"pattern = {pattern!r}; needs 3 finite numbers, not all zero")
    return pat / np.max(np.abs(pat))


def measure_slip_onset(pattern: tuple[float, float, float] = PATTERN,
                       params: OmniParams | None = None
                       ) -> tuple[float, float, float, np.ndarray, np.ndarray]:
    """One ramped run (module docstring).

    Returns:
        ``(measured onset (reading − lag), resolution, predicted onset, scales (N,),
        slip speeds (N, 3))``,
        N·m for the scale of the pattern's largest entry; onset NaN if no wheel slipped.

    Raises:
        ValueError: a bad pattern, or a ramp beyond the actuators' raised torque range.
    """
    pat = _pattern(pattern)
    hy = hybrid(params)
    predicted = predicted_slip_torque(hy, pat, hy.friction)
    if not math.isfinite(predicted):
        raise ValueError(f"pattern {pattern!r} never reaches the traction limit")
    model, data = settled(ActuationMode.TORQUE, params)
    top = RAMP_END * predicted
    for w in WHEELS:  # this scenario needs torques above the drive's own limit
        act = model.actuator(w).id
        model.actuator_forcerange[act] = model.actuator_ctrlrange[act] = (-top, top)
    dt = model.opt.timestep
    n = round(RAMP_TIME / dt)
    rate = (RAMP_END - RAMP_START) * predicted / RAMP_TIME
    scales = RAMP_START * predicted + rate * np.arange(n) * dt
    states = simulate(model, data, scales[:, None] * pat)
    _, twist, th, rates = base_states(model, states[1:])
    slip = np.abs(hy.radius * (rates - oh.rolling_rates(hy, twist, th)))
    below = np.flatnonzero(~(slip > SLIP_SPEED).any(axis=1))
    last = below[-1] + 1 if below.size else 0
    lag = rate * math.sqrt(2 * hy.wheel_inertia * SLIP_SPEED / (hy.radius * rate))
    measured = float(scales[last]) - lag if last < n else math.nan
    return measured, rate * dt, predicted, scales, slip


def evaluate_slip(scenario: Scenario, params: RobotParams | None) -> MeasurementResult:
    """The measured and predicted onset of a push along x (see the module docstring)."""
    if params is not None and not isinstance(params, OmniParams):
        raise ValueError(f"params must be OmniParams, got {type(params).__name__}")
    measured, resolution, predicted, scales, slip = measure_slip_onset(PATTERN, params)
    if not math.isfinite(measured):
        raise ValueError(f"no wheel slipped up to {RAMP_END} × the predicted onset "
                         f"{predicted:.3g} N·m")
    metrics = [Metric("slip-onset torque: predicted vs physics",
                      100 * abs(predicted - measured) / measured, "% of physics", SLIP,
                      f"physics {measured:.4g} ± {resolution:.2g} N·m (the ramp's reading "
                      f"minus its derived lag), predicted {predicted:.4g} N·m"),
               Metric("slip-onset torque, physics", measured, "N·m"),
               Metric("slip-onset torque, predicted", predicted, "N·m"),
               Metric("slip-onset resolution", resolution, "N·m")]
    series = [Series(f"wheel {i + 1}", scales, slip[:, i], "torque scale [N·m]",
                     "slip speed [m/s]") for i in range(3)]
    series.append(Series("predicted onset", np.array([predicted, predicted]),
                         np.array([0.0, float(slip.max())]), "torque scale [N·m]",
                         "slip speed [m/s]"))
    return MeasurementResult(metrics, series)

