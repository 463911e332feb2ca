"""The Whipple bicycle's eigenvalues and self-stability measured from the MuJoCo physics.

Method (linearisation of the simulator's own step map):

1. Steady rolling: the model starts upright at speed ``v`` with wheel rates ``v / r`` and
   rolls for ``settle_time`` so that the soft contacts reach their equilibrium
   penetration. By the bicycle's mirror symmetry the lateral states stay zero (to
   round-off); they are set to exactly zero.
2. ``mujoco.mjd_transitionFD`` (centred differences, ``eps``) gives the one-step map
   ``δx⁺ = A δx`` in MuJoCo's tangent space ``x = (δq, δq̇)`` (free-joint rotation as a
   body-frame rotation vector, linear velocity in the world frame).
3. Mirror symmetry splits ``A`` into a symmetric (pitch, bounce, forward speed, wheel spin)
   and an antisymmetric (lateral) block. The lateral block is expressed with the
   BODY-frame lateral velocity ``u = v_y - v ψ`` (ψ the yaw); in those coordinates the
   lateral position ``y`` and the yaw ψ are cyclic (the physics is invariant under
   translation and rotation about the vertical), so their columns hold nothing but the
   identity and they are dropped. What remains, ``x_r = (φ, δ, u, ω_x, ω_z, δ̇)``, has six
   eigenvalues ``μ``; ``s = log(μ) / Δt``.
4. Of the six, two are the soft contacts' lateral slip ("tyre") modes, absent from the
   knife-edge benchmark: the friction constraint removes a slip velocity at the rate
   ``b = 2 / (d τ_c)`` of its reference, so these modes live on the contact's own time
   scale (``|s| τ_c`` of order 1 or more; measured ≥ 2). The benchmark's four modes are
   those much slower than the contact, ``|s| τ_c < SLOW_LIMIT``; exactly four must be
   (otherwise the measurement raises). Among them a complex pair is weave, the more
   negative real one castering and the other capsize
   (:func:`wmr_mujoco.analytic.whipple.classify`). Their eigenvectors are reported: the
   lean/steer part ``(φ, δ)`` carries the mode (``lean_steer_share``).

The nonlinear check pushes the rolling bicycle sideways (a lean-rate impulse) and follows
its lean for ``duration`` seconds without any control.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

import mujoco
import numpy as np
from scipy.optimize import brentq

from wmr_mujoco.analytic import whipple as analytic
from wmr_mujoco.builders import whipple as builder
from wmr_mujoco.builders.common import to_xml
from wmr_mujoco.builders.scene import add_scene
from wmr_mujoco.whipple_params import DEFAULT_PARAMS, WhippleParams

#: Rolling time before linearising: many contact time constants, s.
SETTLE_TIME = 0.3
#: Finite-difference step of ``mjd_transitionFD``.
FD_EPS = 1e-6
#: Tangent indices (nv = 9): free joint (v_x, v_y, v_z, ω_x, ω_y, ω_z), then
#: rear wheel, steer, front wheel.
_Y, _ROLL, _YAW, _STEER = 1, 3, 5, 7
_NV = 9


def compile_model(params: WhippleParams = DEFAULT_PARAMS) -> mujoco.MjModel:
    """The bicycle on the project's floor, compiled."""
    root = builder.build(params)
    add_scene(root)
    return mujoco.MjModel.from_xml_string(to_xml(root))


def steady_rolling(model: mujoco.MjModel, params: WhippleParams, speed: float,
                   settle_time: float = SETTLE_TIME) -> mujoco.MjData:
    """Upright straight rolling at ``speed`` after the contacts have settled.

    Raises:
        ValueError: ``speed`` is negative or above 30 m/s.
        RuntimeError: the run diverged while settling.
    """
    if not (math.isfinite(speed) and 0.0 <= speed <= 30.0):
        raise ValueError(f"speed = {speed!r} m/s; valid range is [0, 30]")
    data = mujoco.MjData(model)
    data.qpos[:], data.qvel[:] = builder.rolling_state(params, speed)
    for _ in range(round(settle_time / model.opt.timestep)):
        mujoco.mj_step(model, data)
    if not np.all(np.isfinite(data.qpos)) or not np.all(np.isfinite(data.qvel)):
        raise RuntimeError(f"whipple model diverged while settling at {speed} m/s")
    # Remove the round-off in the lateral states (mirror symmetry keeps them zero).
    w, _, y, _ = data.qpos[3:7]
    pitch = 2.0 * math.atan2(y, w)
    data.qpos[3:7] = (math.cos(pitch / 2), 0.0, math.sin(pitch / 2), 0.0)
    data.qpos[1] = 0.0
    data.qpos[8] = 0.0
    data.qvel[[_Y, _ROLL, _YAW, _STEER]] = 0.0
    mujoco.mj_forward(model, data)
    return data


def step_map(model: mujoco.MjModel, data: mujoco.MjData, eps: float = FD_EPS
             ) -> np.ndarray:
    """``A`` of ``δx⁺ = A δx`` by centred finite differences.

    ``mujoco.mjd_transitionFD`` where it applies; MuJoCo 3.17 refuses the RK4 integrator
    there, so for RK4 the same centred differences are taken here with ``mj_step``
    (:func:`step_map_direct`).
    """
    if model.opt.integrator == mujoco.mjtIntegrator.mjINT_RK4:
        return step_map_direct(model, data, eps)
    n = 2 * model.nv + model.na
    a = np.zeros((n, n))
    mujoco.mjd_transitionFD(model, data, eps, True, a, None, None, None)
    return a


def step_map_direct(model: mujoco.MjModel, data: mujoco.MjData, eps: float = FD_EPS
                    ) -> np.ndarray:
    """Centred finite differences of one ``mj_step`` in the tangent space ``(δq, δq̇)``.

    Column ``j``: ``(x⁺(x + ε e_j) ⊖ x⁺(x - ε e_j)) / 2ε``, positions differenced with
    ``mj_differentiatePos`` (quaternions on their tangent space). No actuator state.
    """
    nv = model.nv
    work = mujoco.MjData(model)
    out = np.zeros((2 * nv, 2 * nv))

    def step_from(k: int, h: float) -> tuple[np.ndarray, np.ndarray]:
        mujoco.mj_copyData(work, model, data)
        if k < nv:
            dq = np.zeros(nv)
            dq[k] = h
            mujoco.mj_integratePos(model, work.qpos, dq, 1.0)
        else:
            work.qvel[k - nv] += h
        mujoco.mj_step(model, work)
        return work.qpos.copy(), work.qvel.copy()

    for k in range(2 * nv):
        qp, vp = step_from(k, eps)
        qm, vm = step_from(k, -eps)
        dq = np.zeros(nv)
        mujoco.mj_differentiatePos(model, dq, 1.0, qm, qp)
        out[:nv, k] = dq / (2.0 * eps)
        out[nv:, k] = (vp - vm) / (2.0 * eps)
    return out


def continuous_eigenvalues(a: np.ndarray, dt: float) -> np.ndarray:
    """``s = log(μ) / Δt`` for the eigenvalues ``μ`` of a one-step map."""
    return np.log(np.linalg.eigvals(a).astype(complex)) / dt


def lateral_block(a: np.ndarray, speed: float) -> tuple[np.ndarray, np.ndarray]:
    """The reduced lateral map ``A_r`` on ``(φ, δ, u, ω_x, ω_z, δ̇)``, and its coupling.

    The coupling is the part of the full map that feeds the dropped cyclic coordinates
    (y, ψ) into the kept ones (ideally 0).

    With ``u = v_y - v ψ`` (body-frame lateral velocity at yaw ψ), the change of
    coordinates ``T`` is the identity except ``T[u, ψ] = -v``; ``A' = T A T⁻¹``.
    """
    n = a.shape[0]
    t = np.eye(n)
    t[_NV + _Y, _YAW] = -speed
    a2 = t @ a @ np.linalg.inv(t)
    keep = [_ROLL, _STEER, _NV + _Y, _NV + _ROLL, _NV + _YAW, _NV + _STEER]
    cyclic = [_Y, _YAW]
    return a2[np.ix_(keep, keep)], a2[np.ix_(keep, cyclic)]


#: A benchmark mode is slower than the contact: ``|s| τ_c`` below this.
SLOW_LIMIT = 0.25


def contact_time_constant(model: mujoco.MjModel) -> float:
    """The contact's time constant as MuJoCo uses it: ``max(solref[0], 2 Δt)``, s.

    The wheel geoms' ``solref``, or the largest of the explicit contact pairs' ``solref``
    and ``solreffriction`` where the model has pairs.
    """
    if model.npair:
        tau = float(max(model.pair_solref[:, 0].max(), model.pair_solreffriction[:, 0].max()))
    else:
        tau = float(model.geom_solref[model.geom("rear_wheel_collision").id, 0])
    return max(tau, 2.0 * model.opt.timestep)


@dataclass(frozen=True)
class MeasuredModes:
    """Eigenvalues measured at one speed.

    Attributes:
        speed: forward speed of the rear axle after settling, m/s.
        all_eigenvalues: the six lateral eigenvalues ``s``, s⁻¹.
        slowness: ``|s| τ_c`` of each (same order).
        lean_steer_share: of each eigenvector scaled to the state's natural units
            (angles, and rates over ``|s|``), the share of ``(φ, δ)``: about 0.4 for
            weave and castering, 0.04 for the tyre modes; capsize's falls towards 0 near
            the capsize speed, where the mode becomes a steady turn whose yaw rate over
            ``|s|`` dominates, so the share is reported, not used to pick.
        benchmark: the four picked as the benchmark's, sorted by real part.
        modes: their names (weave, capsize, castering).
        cyclic_coupling: largest entry coupling y, ψ into the kept states (ideally 0).
    """

    speed: float
    all_eigenvalues: np.ndarray
    slowness: np.ndarray
    lean_steer_share: np.ndarray
    benchmark: np.ndarray
    modes: analytic.Modes
    cyclic_coupling: float


def measure_modes(params: WhippleParams, speed: float,
                  model: mujoco.MjModel | None = None) -> MeasuredModes:
    """The bicycle's lateral eigenvalues at ``speed`` from the simulator's step map."""
    model = compile_model(params) if model is None else model
    data = steady_rolling(model, params, speed)
    v = float(data.qvel[0])
    a_r, coupling = lateral_block(step_map(model, data), v)
    mu, vec = np.linalg.eig(a_r)
    s = np.log(mu.astype(complex)) / model.opt.timestep
    slowness = np.abs(s) * contact_time_constant(model)
    pick = np.flatnonzero(slowness < SLOW_LIMIT)
    if len(pick) != 4:
        raise RuntimeError(f"{len(pick)} modes slower than the contact at {v:.3f} m/s "
                           f"(|s| τ_c = {np.round(slowness, 3).tolist()}); expected 4")
    # Position-level share: angles (φ, δ) against the kinematic angles the rates
    # would sweep in one time constant 1/|s| (u over the wheelbase as an angle).
    scaled = np.abs(vec.copy())
    scaled[2] /= params.wheelbase
    scaled[2:] /= np.maximum(np.abs(s), 1e-9)
    share = scaled[:2].sum(axis=0) / scaled.sum(axis=0)
    bench = s[pick]
    bench = bench[np.lexsort((bench.imag, bench.real))]
    return MeasuredModes(speed=v, all_eigenvalues=s, slowness=slowness,
                         lean_steer_share=share, benchmark=bench,
                         modes=analytic.classify(bench, imag_tol=1e-6),
                         cyclic_coupling=float(np.abs(coupling).max()))


def weave_speed(params: WhippleParams, bracket: tuple[float, float] = (3.8, 4.8),
                xtol: float = 1e-5) -> float:
    """Speed where the measured weave pair's real part crosses zero (brentq), m/s."""
    model = compile_model(params)
    return brentq(lambda v: measure_modes(params, v, model).modes.weave.real, *bracket,
                  xtol=xtol)


def capsize_speed(params: WhippleParams, bracket: tuple[float, float] = (5.5, 6.6),
                  xtol: float = 1e-5) -> float:
    """Speed where the measured capsize eigenvalue crosses zero (brentq), m/s."""
    model = compile_model(params)
    return brentq(lambda v: measure_modes(params, v, model).modes.capsize, *bracket,
                  xtol=xtol)


def lean_angle(quat: np.ndarray) -> float:
    """Lean φ (positive to the right) of the rear frame, ``φ = asin(R[2, 1])``.

    R is the body-to-world rotation; ``R[2, 1]`` is the height component of the body's
    y (left) axis, ``sin φ`` for any yaw and pitch in the benchmark's yaw-lean-pitch order.
    """
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, quat)
    return math.asin(max(-1.0, min(1.0, mat[7])))


@dataclass(frozen=True)
class PushResponse:
    """Lean after a sideways push.

    Attributes:
        speed: forward speed before the push, m/s.
        time: sample times after the push, s.
        lean: lean angle φ, rad.
        peak: largest |φ| over the run, rad.
        final_ratio: largest |φ| over the last ``window`` seconds over the peak.
        wall_time: wall-clock time of the run, s.
    """

    speed: float
    time: np.ndarray
    lean: np.ndarray
    peak: float
    final_ratio: float
    wall_time: float


def push_response(params: WhippleParams, speed: float, lean_rate: float = 0.5,
                  duration: float = 10.0, window: float = 2.0,
                  model: mujoco.MjModel | None = None,
                  observer: Callable[[float, mujoco.MjData], None] | None = None
                  ) -> PushResponse:
    """Roll at ``speed``, push sideways, and follow the lean without control.

    The push is a lean rate ``lean_rate`` (rad/s) about the ground line; the run lasts
    ``duration`` s. ``observer(t, data)``, if given, sees every 10 ms sample (for clips).

    The run stops early if the bicycle falls (|φ| > 1.2 rad); a non-finite state raises.
    """
    if not (math.isfinite(lean_rate) and 0.0 < abs(lean_rate) <= 5.0):
        raise ValueError(f"lean_rate = {lean_rate!r} rad/s; valid range is (0, 5] in size")
    model = compile_model(params) if model is None else model
    data = steady_rolling(model, params, speed)
    # A lean rate about the ground line (through both contacts), as the benchmark's φ̇:
    # ω_x at the rear frame and, at the rear axle (height z), v_y = -ω_x z.
    data.qvel[_ROLL] += lean_rate
    data.qvel[_Y] -= lean_rate * data.qpos[2]
    dt = model.opt.timestep
    n = round(duration / dt)
    every = max(1, round(0.01 / dt))
    times, leans = [], []
    t0 = time.perf_counter()
    for k in range(n + 1):
        if k % every == 0:
            times.append(k * dt)
            leans.append(lean_angle(data.qpos[3:7]))
            if observer is not None:
                observer(k * dt, data)
            if abs(leans[-1]) > 1.2:
                break
        mujoco.mj_step(model, data)
    wall = time.perf_counter() - t0
    if not np.all(np.isfinite(data.qpos)):
        raise RuntimeError(f"whipple push run diverged at {speed} m/s")
    t = np.array(times)
    lean = np.array(leans)
    peak = float(np.abs(lean).max())
    late = np.abs(lean[t >= t[-1] - window]).max()
    return PushResponse(speed=speed, time=t, lean=lean, peak=peak,
                        final_ratio=float(late / peak), wall_time=wall)


def real_time_factor(params: WhippleParams, duration: float = 2.0, repeats: int = 3
                     ) -> float:
    """Simulated over wall-clock time of rolling at 5 m/s, one thread.

    Best of ``repeats`` runs, to discount other load on a shared machine.
    """
    model = compile_model(params)
    data = mujoco.MjData(model)
    n = round(duration / model.opt.timestep)
    best = math.inf
    for _ in range(repeats):
        data.qpos[:], data.qvel[:] = builder.rolling_state(params, 5.0)
        t0 = time.perf_counter()
        for _ in range(n):
            mujoco.mj_step(model, data)
        best = min(best, time.perf_counter() - t0)
    return duration / best


def evaluations_per_second(params: WhippleParams) -> float:
    """Force evaluations per simulated second: ``1/Δt``, four times that for RK4."""
    return (4.0 if params.sim.integrator == "RK4" else 1.0) / params.sim.timestep


def with_sim(params: WhippleParams, **changes: object) -> WhippleParams:
    """``params`` with some simulation settings changed."""
    return replace(params, sim=replace(params.sim, **changes))


def eigen_table(params: WhippleParams, speeds: Sequence[float]
                ) -> list[tuple[float, analytic.Modes, analytic.Modes]]:
    """``(v, measured modes, benchmark modes)`` at each speed."""
    model = compile_model(params)
    mats = analytic.matrices(params)
    return [(v, measure_modes(params, v, model).modes, analytic.modes(v, mats))
            for v in speeds]
