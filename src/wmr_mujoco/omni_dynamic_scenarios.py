"""Dynamic scenarios of omni3, judged over the whole run against the model that predicts them.

Each scenario runs the MuJoCo model (physics by contact) and the analytic predictions on
the same inputs and returns a :class:`ScenarioResult`: judged rows
``(metric, value, unit, target, basis)`` and time series of the physics, the kinematic
prediction and the dynamic (hybrid) prediction, for a plot per scenario.

* :func:`step_command` — rate servo, step (no ramp) to a body twist. Dynamic model: the
  hybrid model with the servo law ``τ = clip(k_v (u − θ̇), ±τ_max)`` read from the model.
* :func:`torque_input` — constant wheel torques. Dynamic model: hybrid model, torque law.
* :func:`coasting` — drive at (u, 0, r), then motors off: yaw-rate decay, turn rate of the
  velocity direction, kinetic energy lost per second; hybrid model with its impact map.
* :func:`slip_onset` — constant-torque holds (a push along x), bisected: the torque at
  which a wheel starts to slip, against ``|F_t| = μ N`` (:func:`traction_and_load`).
* :func:`coast_energy_budget` — where a coast's energy goes in the physics (contact
  work by normal/tangential row, single/double roller contact).

``python -m wmr_mujoco.omni_dynamic_scenarios`` runs them all (a few minutes), prints the
tables and pastes them into ``docs/omni-dynamics.md``.
"""

from __future__ import annotations

import argparse
import math
from dataclasses import dataclass, field
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco.actuation import set_actuation_mode
from wmr_mujoco.adapters import base_pose, body_twist
from wmr_mujoco.analytic import omni_hybrid as oh
from wmr_mujoco.analytic import omni_kinematics as ok
from wmr_mujoco.analytic.integrate import integrate
from wmr_mujoco.analytic.omni_dynamics import OmniDynamics
from wmr_mujoco.loading import load
from wmr_mujoco.markers import replace_between
from wmr_mujoco.omni_hybrid_model import WHEELS, drive_from_model, hybrid_from_model, roller_rates
from wmr_mujoco.simulation import check_healthy

#: Targets of issue 16 (requirements).
STEP_PATH_PCT = 0.3
STEP_HEADING_DEG = 0.2
TORQUE_COMPONENT_PCT = 1.0
TORQUE_PATH_PCT = 0.5
COAST_PCT = 5.0
SLIP_PCT = 5.0
SETTLE = 0.5

Row = tuple[str, float, str, float, str]


@dataclass
class ScenarioResult:
    """Judged rows and time series of one scenario.

    ``series`` holds ``t`` and, for ``physics``, ``kinematic`` and ``dynamic``, the pose
    ``(X, Y, ψ)`` and twist ``(u, v, r)`` as ``<model>_pose`` / ``<model>_twist``.
    """

    name: str
    rows: list[Row]
    series: dict[str, np.ndarray] = field(default_factory=dict)

    @property
    def passed(self) -> bool:
        """All rows with a target meet it (|value| ≤ target)."""
        return all(abs(v) <= tgt for _, v, _, tgt, _ in self.rows if math.isfinite(tgt))


def _fmt(values: np.ndarray) -> str:
    """``(0.3, 0, 1)``: a vector for a scenario name."""
    return "(" + ", ".join(f"{float(x):g}" for x in values) + ")"


def _finite_vector(name: str, value: object, n: int) -> np.ndarray:
    arr = np.asarray(value, dtype=float)
    if arr.shape != (n,):
        raise ValueError(f"{name} must have shape ({n},), got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} = {arr}; every entry must be finite")
    return arr


def _duration(value: float) -> float:
    if not isinstance(value, (int, float)) or not math.isfinite(value) or not 0 < value <= 30:
        raise ValueError(f"duration = {value!r}; valid range is (0, 30] s")
    return float(value)


def _settled(mode: str, contact_timeconst: float | None = None
             ) -> tuple[mujoco.MjModel, mujoco.MjData]:
    """omni3 in ``mode``, settled on the floor.

    ``contact_timeconst`` (optional) stiffens the roller contacts: their solref time
    constant, with the timestep set to half of it (MuJoCo needs ≥ 2 steps per constant).
    """
    model = load("omni3")
    if contact_timeconst is not None:
        if not math.isfinite(contact_timeconst) or not 0 < contact_timeconst <= 0.1:
            raise ValueError(f"contact_timeconst = {contact_timeconst!r}; valid range is "
                             f"(0, 0.1] s")
        rollers = [g for g in range(model.ngeom)
                   if model.geom_conaffinity[g] and model.geom_bodyid[g] != 0]
        model.geom_solref[rollers, 0] = contact_timeconst
        model.opt.timestep = contact_timeconst / 2.0
    set_actuation_mode(model, mode)
    data = mujoco.MjData(model)
    for _ in range(round(SETTLE / model.opt.timestep)):
        mujoco.mj_step(model, data)
    mujoco.mj_forward(model, data)
    return model, data


def _state(model: mujoco.MjModel, data: mujoco.MjData) -> tuple[np.ndarray, ...]:
    thetas = np.array([data.joint(w).qpos[0] for w in WHEELS])
    return base_pose(model, data), body_twist(model, data), thetas, roller_rates(model, data)


def _physics(model: mujoco.MjModel, data: mujoco.MjData, ctrl: np.ndarray
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Step with ``ctrl[k]`` (N, 3): pose, twist (N + 1, 3) and wheel rates."""
    acts = [model.actuator(w).id for w in WHEELS]
    n = ctrl.shape[0]
    pose, twist, rates = np.zeros((n + 1, 3)), np.zeros((n + 1, 3)), np.zeros((n + 1, 3))
    pose[0], twist[0] = base_pose(model, data), body_twist(model, data)
    rates[0] = [data.joint(w).qvel[0] for w in WHEELS]
    for k in range(n):
        data.ctrl[acts] = ctrl[k]
        mujoco.mj_step(model, data)
        mujoco.mj_forward(model, data)
        pose[k + 1], twist[k + 1] = base_pose(model, data), body_twist(model, data)
        rates[k + 1] = [data.joint(w).qvel[0] for w in WHEELS]
    check_healthy(model, data)
    return pose, twist, rates


def _relative(pose: np.ndarray, start: np.ndarray) -> np.ndarray:
    """Pose in the start frame (so every model starts at the origin, heading 0)."""
    d = pose[:, :2] - start[:2]
    c, s = math.cos(start[2]), math.sin(start[2])
    heading = np.angle(np.exp(1j * (pose[:, 2] - start[2])))
    return np.column_stack([c * d[:, 0] + s * d[:, 1], -s * d[:, 0] + c * d[:, 1],
                            np.unwrap(heading)])


def _lagrange(hy: oh.OmniHybrid) -> OmniDynamics:
    """The reduced Lagrange model (no rows, impacts, rollers or slip) of the same robot."""
    return OmniDynamics(hy.mass, float(hy.inertia[2, 2]), hy.wheel_inertia,
                        ok.symmetric_layout(hy.radius, hy.distance))


def _substeps(dt: float) -> int:
    """RK4 steps per output step: at most 1 ms each (the servo's time constant is ~4 ms)."""
    return max(1, math.ceil(dt / 1e-3 - 1e-9))


def _kinematic_pose(twist: np.ndarray, dt: float) -> np.ndarray:
    """Integrate a body twist series (N + 1, 3) from the origin (midpoint rule)."""
    pose = np.zeros_like(twist)
    for k in range(twist.shape[0] - 1):
        nu = 0.5 * (twist[k] + twist[k + 1])
        psi = pose[k, 2] + 0.5 * dt * nu[2]
        pose[k + 1] = pose[k] + dt * ok.body_to_world(psi, nu)
    return pose


def _path(pose: np.ndarray, distance: float) -> float:
    """Path of a point at radius L on the platform: ``Σ √(|Δp|² + (L Δψ)²)``.

    For a translation this is the centre's path; for a pure rotation (centre at rest) it
    is the arc the wheels' centres travel, so "% of path" stays defined.
    """
    step = np.diff(pose, axis=0)
    return float(np.sum(np.sqrt(np.sum(step[:, :2] ** 2, axis=1)
                                + (distance * step[:, 2]) ** 2)))


def _pose_rows(prefix: str, ref: np.ndarray, other: np.ndarray, path_pct: float,
               heading_deg: float, basis: str, distance: float) -> list[Row]:
    path = max(_path(ref, distance), 1e-9)
    dist = np.linalg.norm(other[:, :2] - ref[:, :2], axis=1)
    head = np.degrees(np.abs(other[:, 2] - ref[:, 2]))
    rows: list[Row] = [
        (f"{prefix} position error, worst, % of path", 100 * dist.max() / path, "%",
         path_pct, basis),
        (f"{prefix} position error, RMS, % of path", 100 * math.sqrt(np.mean(dist ** 2)) / path,
         "%", math.inf, "report"),
        (f"{prefix} heading error, worst", head.max(), "deg", heading_deg,
         basis if math.isfinite(heading_deg) else "report"),
        (f"{prefix} heading error, RMS", math.sqrt(np.mean(head ** 2)), "deg", math.inf,
         "report"),
        (f"{prefix} final position error, % of path", 100 * dist[-1] / path, "%", math.inf,
         "report"),
    ]
    return rows


def _twist_rows(prefix: str, ref: np.ndarray, other: np.ndarray, pct: float,
                distance: float) -> list[Row]:
    """Max and RMS error of u, v (m/s) and r (rad/s), each also as % of its scale.

    Scales: u and v: ``max(peak planar speed, L · peak |r|)``; r: ``max(peak |r|, peak
    speed / L)``: a component that stays zero is judged against the speed the run's
    motion gives the wheels (L · r is the rim speed of pure rotation).
    """
    speed = float(np.max(np.linalg.norm(ref[:, :2], axis=1)))
    peak_r = float(np.max(np.abs(ref[:, 2])))
    lin = max(speed, distance * peak_r)
    scales = (lin, lin, lin / distance)
    rows: list[Row] = []
    for j, (name, unit) in enumerate((("u", "m/s"), ("v", "m/s"), ("r", "rad/s"))):
        err = np.abs(other[:, j] - ref[:, j])
        scale = max(scales[j], 1e-9)
        rows += [(f"{prefix} {name} error, worst", float(err.max()), unit, math.inf, "report"),
                 (f"{prefix} {name} error, RMS", float(math.sqrt(np.mean(err ** 2))), unit,
                  math.inf, "report"),
                 (f"{prefix} {name} error, worst, % of peak", 100 * float(err.max()) / scale,
                  "%", pct, "requirement (issue 16)" if math.isfinite(pct) else "report")]
    return rows


def _series(t: np.ndarray, **models: tuple[np.ndarray, np.ndarray]) -> dict[str, np.ndarray]:
    out = {"t": t}
    for name, (pose, twist) in models.items():
        out[f"{name}_pose"], out[f"{name}_twist"] = pose, twist
    return out


def step_command(twist: tuple[float, float, float], duration: float = 2.0,
                 name: str | None = None) -> ScenarioResult:
    """Rate servo commanded a constant twist from rest, no ramp.

    Raises:
        ValueError: non-finite twist, or a duration outside (0, 30] s.
    """
    nu_cmd = _finite_vector("twist", twist, 3)
    duration = _duration(duration)
    model, data = _settled("rate")
    hy = hybrid_from_model(model)
    drive = drive_from_model(model, "rate")
    dt = model.opt.timestep
    n = round(duration / dt)
    H = ok.wheel_jacobian(ok.symmetric_layout(hy.radius, hy.distance))
    rates = np.tile(H @ nu_cmd, (n, 1))
    if np.any(np.abs(rates) > float(model.actuator(WHEELS[0]).ctrlrange[1])):
        raise ValueError(f"twist {nu_cmd} needs wheel rates {H @ nu_cmd} beyond the rate "
                         f"limit ±{model.actuator(WHEELS[0]).ctrlrange[1]:g} rad/s")
    start, nu0, th0, spins = _state(model, data)
    pose, tw, _ = _physics(model, data, rates)
    phys = _relative(pose, start)
    run = oh.simulate(hy, drive, rates, dt, np.zeros(3), nu0, th0, spins)
    kin_twist = np.vstack([nu0, np.tile(nu_cmd, (n, 1))])
    kin = _kinematic_pose(kin_twist, dt)
    basis = "requirement (issue 16)"
    rows = (_pose_rows("dynamic", phys, run.pose, STEP_PATH_PCT, STEP_HEADING_DEG, basis,
                       hy.distance)
            + _twist_rows("dynamic", tw, run.twist, math.inf, hy.distance)
            + _pose_rows("kinematic", phys, kin, math.inf, math.inf, "report", hy.distance))
    return ScenarioResult(name or f"step {_fmt(nu_cmd)}", rows,
                          _series(run.t, physics=(phys, tw), kinematic=(kin, kin_twist),
                                  dynamic=(run.pose, run.twist)))


def torque_input(torques: tuple[float, float, float], duration: float = 2.0,
                 name: str | None = None) -> ScenarioResult:
    """Constant wheel torques from rest (torque mode).

    Kinematic prediction: the measured wheel rates through ``ν = H⁻¹ θ̇``.

    Raises:
        ValueError: non-finite torques, torques beyond the torque limit, bad duration.
    """
    tau = _finite_vector("torques", torques, 3)
    duration = _duration(duration)
    model, data = _settled("torque")
    limit = float(model.actuator(WHEELS[0]).forcerange[1])
    if np.any(np.abs(tau) > limit):
        raise ValueError(f"torques = {tau}; valid range is [−{limit:g}, {limit:g}] N·m")
    hy = hybrid_from_model(model)
    dt = model.opt.timestep
    n = round(duration / dt)
    inputs = np.tile(tau, (n, 1))
    start, nu0, th0, spins = _state(model, data)
    pose, tw, wheel_rates = _physics(model, data, inputs)
    phys = _relative(pose, start)
    run = oh.simulate(hy, drive_from_model(model, "torque"), inputs, dt, np.zeros(3), nu0,
                      th0, spins)
    H = ok.wheel_jacobian(ok.symmetric_layout(hy.radius, hy.distance))
    kin_twist = np.linalg.solve(H, wheel_rates.T).T
    kin = _kinematic_pose(kin_twist, dt)
    lag = integrate(lambda x, u: _lagrange(hy).state_derivative(x, u),
                    np.concatenate([np.zeros(3), nu0]), inputs, dt)
    final = float(np.linalg.norm(lag[-1, 3:] - tw[-1]) / np.linalg.norm(tw[-1]))
    basis = "requirement (issue 16)"
    rows = (_twist_rows("dynamic", tw, run.twist, TORQUE_COMPONENT_PCT, hy.distance)
            + _pose_rows("dynamic", phys, run.pose, TORQUE_PATH_PCT, math.inf, basis,
                         hy.distance)
            + _pose_rows("kinematic", phys, kin, math.inf, math.inf, "report", hy.distance)
            + _twist_rows("lagrange", tw, lag[:, 3:], math.inf, hy.distance)
            + [("lagrange norm(Δν) / norm(ν) at the last instant (old metric, mixed units)",
                100 * final, "%", math.inf, "report: the single-instant figure")])
    return ScenarioResult(name or f"torque {_fmt(tau)}", rows,
                          _series(run.t, physics=(phys, tw), kinematic=(kin, kin_twist),
                                  dynamic=(run.pose, run.twist),
                                  lagrange=(lag[:, :3], lag[:, 3:])))


def _slope(t: np.ndarray, y: np.ndarray) -> float:
    """Least-squares slope of ``y(t)`` over the whole run."""
    return float(np.polyfit(t, y, 1)[0])


def _coast_figures(t: np.ndarray, pose: np.ndarray, twist: np.ndarray, energy: np.ndarray
                   ) -> tuple[float, float, float]:
    """Yaw-rate decay (rad/s²), velocity-direction turn rate (rad/s), energy loss (W).

    Each the least-squares slope over the whole coast (the twist and the planar energy
    ripple within every roller pitch, so two end samples would depend on where in a
    pitch they fall): ``−dr/dt``, ``dχ/dt`` with χ the world direction of the velocity,
    ``−dT/dt``.
    """
    c, s = np.cos(pose[:, 2]), np.sin(pose[:, 2])
    vx = c * twist[:, 0] - s * twist[:, 1]
    vy = s * twist[:, 0] + c * twist[:, 1]
    chi = np.unwrap(np.arctan2(vy, vx))
    return -_slope(t, twist[:, 2]), _slope(t, chi), -_slope(t, energy)


def coasting(twist: tuple[float, float, float] = (0.3, 0.0, 1.0), drive_time: float = 1.5,
             duration: float = 3.0, impacts: bool = True,
             contact_timeconst: float | None = None) -> ScenarioResult:
    """Drive at ``twist`` (0.5 s ramp), then motors off (torque mode, τ = 0) and coast.

    Physics and hybrid model start the coast from the same measured state (twist, wheel
    angles, roller spins). Energy: ``½ νᵀ M(σ, θ) ν`` of the hybrid model's planar
    mass matrix, evaluated on both. Kinematic prediction: the twist at motor-off, held.
    ``contact_timeconst`` stiffens the contacts (see :func:`_settled`), to check the
    rigid-limit impact map.

    Raises:
        ValueError: non-finite twist or a duration outside (0, 30] s.
    """
    nu_cmd = _finite_vector("twist", twist, 3)
    duration = _duration(duration)
    drive_time = _duration(drive_time)
    model, data = _settled("rate", contact_timeconst)
    hy = hybrid_from_model(model)
    dt = model.opt.timestep
    H = ok.wheel_jacobian(ok.symmetric_layout(hy.radius, hy.distance))
    nd = round(drive_time / dt)
    ramp = np.clip(np.arange(nd) * dt / 0.5, 0.0, 1.0)[:, None]
    _physics(model, data, ramp * (H @ nu_cmd))
    set_actuation_mode(model, "torque")
    n = round(duration / dt)
    zeros = np.zeros((n, 3))
    start, nu0, th0, spins = _state(model, data)
    pose, tw, wheel_rates = _physics(model, data, zeros)
    phys = _relative(pose, start)
    run = oh.simulate(hy, drive_from_model(model, "torque"), zeros, dt, np.zeros(3), nu0,
                      th0, spins, impacts=impacts, substeps=_substeps(dt))
    # Wheel angles of the physics, integrated from the measured rates, for M(σ, θ).
    th_phys = th0 + np.concatenate([[np.zeros(3)], np.cumsum(
        0.5 * (wheel_rates[1:] + wheel_rates[:-1]) * dt, axis=0)])
    e_phys = np.array([hy.kinetic_energy(v, hy.modes(th), th) for v, th in zip(tw, th_phys,
                                                                               strict=True)])
    e_dyn = np.array([hy.kinetic_energy(v, hy.modes(th), th)
                      for v, th in zip(run.twist, run.thetas, strict=True)])
    kin_twist = np.tile(nu0, (n + 1, 1))
    kin = _kinematic_pose(kin_twist, dt)
    fp = _coast_figures(run.t, phys, tw, e_phys)
    fd = _coast_figures(run.t, run.pose, run.twist, e_dyn)
    rows: list[Row] = []
    for name, unit, a, b in (("yaw-rate decay", "rad/s²", fp[0], fd[0]),
                             ("velocity-direction turn rate", "rad/s", fp[1], fd[1]),
                             ("energy lost per second", "W", fp[2], fd[2])):
        rows += [(f"physics {name}", a, unit, math.inf, "report"),
                 (f"dynamic {name}", b, unit, math.inf, "report"),
                 (f"dynamic {name} error, % of physics", 100 * abs(b - a) / max(abs(a), 1e-12),
                  "%", COAST_PCT, "requirement (issue 16)")]
    rows.append(("impact-map energy, per second", sum(s[2] for s in run.switches) / duration,
                 "W", math.inf, "report"))
    series = _series(run.t, physics=(phys, tw), kinematic=(kin, kin_twist),
                     dynamic=(run.pose, run.twist))
    series["physics_energy"], series["dynamic_energy"] = e_phys, e_dyn
    return ScenarioResult(f"coast after {_fmt(nu_cmd)}", rows, series)


def traction_and_load(hy: oh.OmniHybrid, torques: np.ndarray
                      ) -> tuple[np.ndarray, np.ndarray]:
    """Traction ``F_t`` (N, along t_i) and normal loads ``N`` (N) under ``torques`` at rest.

    ``ν̇ = (P + I_w HᵀH)⁻¹ Hᵀ τ`` (mean row lever L), ``F_t = (τ − I_w H ν̇)/r``; loads
    from :meth:`OmniHybrid.normal_loads` (moment balance about the centre of mass).
    """
    H = ok.wheel_jacobian(ok.symmetric_layout(hy.radius, hy.distance))
    P = np.diag([hy.mass, hy.mass, hy.inertia[2, 2]])
    nudot = np.linalg.solve(P + hy.wheel_inertia * H.T @ H, H.T @ torques)
    thdd = H @ nudot
    force = (torques - hy.wheel_inertia * thdd) / hy.radius
    return force, hy.normal_loads(force, thdd)


def predicted_slip_torque(hy: oh.OmniHybrid, pattern: np.ndarray, friction: float) -> float:
    """Scale s of ``τ = s · pattern`` at which the first wheel reaches ``|F_t| = μ N``.

    ``F_t`` is linear in s and ``N = N₀ + s N₁`` affine (:func:`traction_and_load`), so
    each wheel's onset solves ``s |F₁| = μ (N₀ + s N₁)``.
    """
    f1, n1_total = traction_and_load(hy, pattern)
    _, n0 = traction_and_load(hy, np.zeros(3))
    n1 = n1_total - n0
    onsets = [friction * n0[i] / (abs(f1[i]) - friction * n1[i])
              for i in range(3) if abs(f1[i]) - friction * n1[i] > 0]
    return min(onsets) if onsets else math.inf


def _slips(pattern: np.ndarray, scale: float, hold: float, threshold: float,
           torque_limit: float) -> tuple[bool, np.ndarray]:
    """Apply ``scale · pattern`` from rest for ``hold`` s and report whether a wheel slips.

    True if the mean contact slip speed of any wheel over the second half of the hold
    exceeds ``threshold``; also returns those means.
    """
    model, data = _settled("torque")
    for w in WHEELS:
        act = model.actuator(w).id
        model.actuator_forcerange[act] = model.actuator_ctrlrange[act] = (-torque_limit,
                                                                         torque_limit)
    hy = hybrid_from_model(model)
    dt = model.opt.timestep
    n = round(hold / dt)
    _, _, th0, _ = _state(model, data)
    _, tw, wheel_rates = _physics(model, data, np.tile(scale * pattern, (n, 1)))
    th = th0 + np.concatenate([[np.zeros(3)], np.cumsum(
        0.5 * (wheel_rates[1:] + wheel_rates[:-1]) * dt, axis=0)])
    slip = np.array([np.abs(hy.radius * (w - hy.jacobian(hy.modes(a)) @ v))
                     for w, a, v in zip(wheel_rates, th, tw, strict=True)])
    mean = slip[n // 2:].mean(axis=0)
    return bool(np.any(mean > threshold)), mean


def slip_onset(pattern: tuple[float, float, float] = (0.0, -1.0, 1.0), hold: float = 0.12,
               threshold: float = 0.01, torque_limit: float = 3.0, low: float = 0.3,
               high: float = 2.0, iterations: int = 7) -> ScenarioResult:
    """Torque at which a wheel starts to slip, by bisection on constant-torque holds.

    Torques ``τ = s · pattern`` (default: a push along x), from rest; the result is s.

    A hold of ``hold`` seconds keeps the robot slow (the hand-over impacts of a fast
    robot modulate the normal loads and would make slip a dynamic, not a traction,
    event). Slip speed of wheel i: ``|R (θ̇_i − (H(σ) ν)_i)|`` from the measured rates;
    a hold slips if its mean over the second half exceeds ``threshold``. The actuators'
    torque limit is raised to ``torque_limit`` for this scenario. Resolution of the
    measured onset: ``(high − low) / 2^iterations``.

    Raises:
        ValueError: a non-finite or zero pattern, non-positive settings, ``low ≥ high``.
    """
    pat = _finite_vector("pattern", pattern, 3)
    if not np.any(pat):
        raise ValueError("pattern = (0, 0, 0); it must have a nonzero entry")
    for name, value in (("hold", hold), ("threshold", threshold),
                        ("torque_limit", torque_limit), ("low", low), ("high", high)):
        if not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
            raise ValueError(f"{name} = {value!r}; valid range is (0, inf)")
    if low >= high or high > torque_limit:
        raise ValueError(f"low = {low!r}, high = {high!r}; need 0 < low < high ≤ "
                         f"torque_limit = {torque_limit!r}")
    if not isinstance(iterations, int) or not 1 <= iterations <= 20:
        raise ValueError(f"iterations = {iterations!r}; valid range is integers [1, 20]")
    pat = pat / np.max(np.abs(pat))
    lo, hi = low, high
    trace = []
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        slipped, mean = _slips(pat, mid, hold, threshold, torque_limit)
        trace.append((mid, float(mean.max())))
        lo, hi = (lo, mid) if slipped else (mid, hi)
    measured = 0.5 * (lo + hi)
    model = load("omni3")
    hy = hybrid_from_model(model)
    predicted = predicted_slip_torque(hy, pat, hy.friction)
    rows: list[Row] = [
        ("physics slip-onset torque", measured, "N·m", math.inf,
         f"report (± {(high - low) / 2 ** (iterations + 1):.3g})"),
        ("predicted slip-onset torque", predicted, "N·m", math.inf, "report"),
        ("slip-onset torque error, % of physics", 100 * abs(predicted - measured) / measured,
         "%", SLIP_PCT, "requirement (issue 16)")]
    arr = np.asarray(trace)
    series = {"scale": arr[:, 0], "mean_slip_speed": arr[:, 1]}
    return ScenarioResult(f"slip onset {_fmt(pat)}", rows, series)


def coast_energy_budget(twist: tuple[float, float, float] = (0.3, 0.0, 1.0),
                        drive_time: float = 1.5, duration: float = 3.0,
                        contact_timeconst: float | None = None) -> ScenarioResult:
    """Where a coast's kinetic energy goes, measured in the physics, step by step.

    The work of every contact constraint force over a step, ``f · J (q̇ₖ + q̇ₖ₊₁)/2 Δt``,
    split into its normal row (contact damping: the hand-over impacts and the soft
    contact's own loss) and its tangential rows (slip), and by whether two rollers of
    that wheel touch at once (the rows' overlap). Their sum is checked against the
    change of kinetic + potential energy (closure row).

    Raises:
        ValueError: non-finite twist, bad duration or contact time constant.
    """
    nu_cmd = _finite_vector("twist", twist, 3)
    duration, drive_time = _duration(duration), _duration(drive_time)
    model, data = _settled("rate", contact_timeconst)
    model.opt.enableflags |= mujoco.mjtEnableBit.mjENBL_ENERGY
    hy = hybrid_from_model(model, compliant=False)
    dt = model.opt.timestep
    H = ok.wheel_jacobian(ok.symmetric_layout(hy.radius, hy.distance))
    nd = round(drive_time / dt)
    ramp = np.clip(np.arange(nd) * dt / 0.5, 0.0, 1.0)[:, None]
    _physics(model, data, ramp * (H @ nu_cmd))
    set_actuation_mode(model, "torque")
    data.ctrl[:] = 0.0
    mujoco.mj_forward(model, data)
    energy0 = float(data.energy[0] + data.energy[1])
    wheel_of = {model.body(w).id: i for i, w in enumerate(WHEELS)}
    floor = model.geom("floor").id
    work = {"single normal": 0.0, "single tangential": 0.0, "overlap normal": 0.0,
            "overlap tangential": 0.0}
    contact_floor = int(mujoco.mjtConstraint.mjCNSTR_CONTACT_FRICTIONLESS)
    for _ in range(round(duration / dt)):
        q0 = data.qvel.copy()
        mujoco.mj_step(model, data)
        jv = np.zeros(data.nefc)
        mujoco.mj_mulJacVec(model, data, jv, 0.5 * (q0 + data.qvel))
        wheel = np.full(data.ncon, -1)
        for ci, c in enumerate(data.contact[:data.ncon]):
            geom = c.geom2 if c.geom1 == floor else c.geom1
            wheel[ci] = wheel_of.get(int(model.body_parentid[model.geom_bodyid[geom]]), -1)
        per_wheel = np.bincount(wheel[wheel >= 0], minlength=3)
        for j in range(data.nefc):
            ci = int(data.efc_id[j])
            if data.efc_type[j] < contact_floor or ci >= data.ncon or wheel[ci] < 0:
                continue
            normal = j == 0 or data.efc_id[j - 1] != ci or data.efc_type[j - 1] < contact_floor
            key = ("overlap " if per_wheel[wheel[ci]] >= 2 else "single ") + (
                "normal" if normal else "tangential")
            work[key] += float(data.efc_force[j] * jv[j]) * dt
    check_healthy(model, data)
    mujoco.mj_forward(model, data)
    change = float(data.energy[0] + data.energy[1]) - energy0
    total = sum(work.values())
    rows: list[Row] = [(f"contact work, {k}, per second", v / duration, "W", math.inf,
                        "report") for k, v in work.items()]
    rows += [("contact work, total, per second", total / duration, "W", math.inf, "report"),
             ("mechanical energy change per second", change / duration, "W", math.inf,
              "report"),
             ("closure: (work − change) / change", abs(total - change) / max(abs(change),
                                                                               1e-12),
              "-", math.inf, "report")]
    tc = "default contacts" if contact_timeconst is None else f"solref {contact_timeconst:g} s"
    return ScenarioResult(f"coast energy budget {_fmt(nu_cmd)}, {tc}",
                          rows)


def all_scenarios(speed: float = 0.3, yaw_rate: float = 1.0) -> list[ScenarioResult]:
    """Every scenario of issue 16 (a few minutes)."""
    out = [step_command((speed * math.cos(math.radians(d)), speed * math.sin(math.radians(d)),
                         0.0), name=f"step {d}°") for d in range(0, 360, 45)]
    out.append(step_command((0.0, 0.0, yaw_rate), name="step rotate"))
    out.append(step_command((speed, 0.0, 0.5 * yaw_rate), name="step translate+rotate"))
    out += [torque_input((0.0, -0.03, 0.03), name="torque along x"),
            torque_input((0.04, -0.02, -0.02), name="torque along y"),
            torque_input((0.02, 0.02, 0.02), name="torque rotate"),
            torque_input((0.04, -0.03, 0.01), name="torque combined"),
            coasting(), slip_onset()]
    return out


DOC = Path(__file__).resolve().parents[2] / "docs" / "omni-dynamics.md"


def markdown(results: list[ScenarioResult]) -> str:
    """One table of every judged and reported row."""
    lines = ["| scenario | metric | value | unit | target | basis |", "|---|---|---|---|---|---|"]
    for res in results:
        for metric, value, unit, target, basis in res.rows:
            tgt = f"≤ {target:g}" if math.isfinite(target) else ""
            mark = "" if not math.isfinite(target) else (" ✓" if abs(value) <= target
                                                         else " ✗")
            lines.append(f"| {res.name} | {metric} | {value:.4g}{mark} | {unit} | {tgt} | "
                         f"{basis} |")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:  # pragma: no cover - a few minutes
    """Run every scenario and the coasting energy budgets; print and paste the tables."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--no-write", action="store_true", help="print only")
    args = parser.parse_args(argv)
    results = all_scenarios()
    budgets = [coast_energy_budget(), coast_energy_budget(contact_timeconst=0.001,
                                                          duration=2.0),
               coast_energy_budget((0.3, 0.0, 0.0))]
    res_md, bud_md = markdown(results), markdown(budgets)
    print(res_md, "", bud_md, sep="\n")
    if not args.no_write:
        replace_between(DOC, "omni dynamics: results", res_md)
        replace_between(DOC, "omni dynamics: energy budget", bud_md)
        print(f"wrote {DOC}")


if __name__ == "__main__":  # pragma: no cover
    main()
