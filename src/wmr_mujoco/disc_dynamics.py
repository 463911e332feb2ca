"""Rolling and sliding disc scenarios: MuJoCo against the classic solutions.

Free disc (``disc_free``: free joint, no actuators, contact only) against
:mod:`wmr_mujoco.analytic.rolling_disc`, and the driven wheel on its mount (``disc``)
against :class:`~wmr_mujoco.analytic.wheel_dynamics.SlipPulse`. Every scenario starts the
simulation on the analytic initial state, runs it by contact physics alone, and judges
the difference over the whole run (worst and RMS) in the quantity's own unit. Each
returns a :class:`ScenarioResult`: judged :class:`Metric` rows plus time series for plots.

Targets (all requirements of issue 13): incline acceleration 0.5 %; stability threshold
speed 2 %; steady precession lean and circle radius 1 % over a full circle; leaning start
path 1 % of path length and lean 1°; energy drift 0.5 % over 10 s; sliding wheel onset
torque, sliding accelerations and re-grip time 2 %.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import mujoco
import numpy as np
from scipy.integrate import solve_ivp

from wmr_mujoco.actuation import set_actuation_mode
from wmr_mujoco.analytic.rolling_disc import (
    RollingDisc,
    check_incline,
    check_lean,
    check_rate,
)
from wmr_mujoco.analytic.wheel_dynamics import SlipPulse, WheelDynamics
from wmr_mujoco.simulation import check_healthy

REQUIREMENT = "requirement (issue 13)"


@dataclass(frozen=True)
class Metric:
    """One judged figure: ``value`` must be at most ``target`` (both in ``unit``)."""

    name: str
    value: float
    unit: str
    target: float
    basis: str

    @property
    def passed(self) -> bool:
        """``value <= target`` (and finite)."""
        return bool(np.isfinite(self.value) and self.value <= self.target)

    def row(self) -> tuple[str, float, str, float, str]:
        """``(name, value, unit, target, basis)``."""
        return (self.name, self.value, self.unit, self.target, self.basis)


@dataclass(frozen=True)
class ScenarioResult:
    """Judged metrics and plot series (name → ``(t, columns...)`` array) of one scenario."""

    name: str
    metrics: tuple[Metric, ...]
    series: dict[str, np.ndarray] = field(default_factory=dict)

    @property
    def passed(self) -> bool:
        """Every metric within its target."""
        return all(m.passed for m in self.metrics)


def _worst_rms(err: np.ndarray) -> tuple[float, float]:
    e = np.abs(np.asarray(err, float))
    return float(e.max()), float(np.sqrt(np.mean(e**2)))


def _pair(name: str, err: np.ndarray, unit: str, target: float,
          basis: str = REQUIREMENT) -> tuple[Metric, Metric]:
    worst, rms = _worst_rms(err)
    return (Metric(f"{name} worst", worst, unit, target, basis),
            Metric(f"{name} RMS", rms, unit, target, basis))


# --- the free disc in MuJoCo -----------------------------------------------------------
def disc_from_model(model: mujoco.MjModel) -> RollingDisc:
    """Thin-disc constants of the compiled free disc: mass, inertias, radius, gravity."""
    b = model.body("disc").id
    inertia = model.body_inertia[b]
    return RollingDisc(radius=float(model.geom("disc_collision").size[0]),
                       mass=float(model.body_mass[b]), axial_inertia=float(inertia[1]),
                       diametral_inertia=float(inertia[0]),
                       gravity=float(np.linalg.norm(model.opt.gravity)))


def set_free_state(model: mujoco.MjModel, data: mujoco.MjData, disc: RollingDisc,
                   state: np.ndarray) -> None:
    """Put the free disc on the analytic ``state`` (spin angle 0), touching the floor.

    Orientation ``R = R_z(ψ) R_x(θ)`` (body x = ê1, y = axle ê2, z = ê3); centre height
    the collision ellipsoid's support ``√(a² cos² θ + b² sin² θ)`` (cylinder:
    ``a cos θ + b |sin θ|``); linear velocity
    ``v_G = a (ω2 ê1 − ω1 ê2)``; body angular velocity ``(ω1, ω2, ω3)``.
    """
    mujoco.mj_resetData(model, data)
    psi, th = state[2], state[3]
    quat = np.zeros(4)
    mujoco.mju_mulQuat(quat, np.array([math.cos(psi / 2), 0, 0, math.sin(psi / 2)]),
                       np.array([math.cos(th / 2), math.sin(th / 2), 0, 0]))
    a, b = model.geom("disc_collision").size[:2]
    centre = disc.centre(state)
    if model.geom("disc_collision").type[0] == mujoco.mjtGeom.mjGEOM_CYLINDER:
        centre[2] = a * math.cos(th) + b * abs(math.sin(th))  # the rim edge touches
    else:
        centre[2] = math.hypot(a * math.cos(th), b * math.sin(th))
    data.qpos[:3] = centre
    data.qpos[3:7] = quat
    data.qvel[:3] = disc.centre_velocity(state)
    data.qvel[3:6] = state[5:8]
    mujoco.mj_forward(model, data)


def free_pose(model: mujoco.MjModel, data: mujoco.MjData, radius: float) -> np.ndarray:
    """``(x_P, y_P, ψ, θ, ω1, ω2, ω3, E)`` of the free disc now.

    Axle ê2 = body y; lean ``θ = asin(ê2_z)``; ê1 = ê2 × ẑ normalised; contact point
    ``P = G − a ê3`` (the thin-disc contact); ω in the tilted frame; energy
    ``E = ½ m v² + ½ ωᵀ I ω + m g z_G``.
    """
    b = model.body("disc").id
    rot = data.xmat[b].reshape(3, 3)
    e2 = rot[:, 1]
    th = math.asin(float(np.clip(e2[2], -1.0, 1.0)))
    e1 = np.cross(e2, [0.0, 0.0, 1.0])
    e1 /= np.linalg.norm(e1)
    e3 = np.cross(e1, e2)
    p = data.xpos[b] - radius * e3
    w_world = rot @ data.qvel[3:6]
    m = model.body_mass[b]
    g = -model.opt.gravity
    energy = (0.5 * m * data.qvel[:3] @ data.qvel[:3]
              + 0.5 * data.qvel[3:6] @ (model.body_inertia[b] * data.qvel[3:6])
              + m * g @ data.xpos[b])
    return np.array([p[0], p[1], math.atan2(e1[1], e1[0]), th, w_world @ e1,
                     w_world @ e2, w_world @ e3, energy])


def _run_free(model: mujoco.MjModel, data: mujoco.MjData, duration: float,
              radius: float, stop=None) -> np.ndarray:
    """Step ``duration`` s; rows ``(t, free_pose...)``. Diverging runs raise."""
    n = round(duration / model.opt.timestep)
    rows = np.empty((n + 1, 9))
    rows[0] = [data.time, *free_pose(model, data, radius)]
    for k in range(1, n + 1):
        mujoco.mj_step(model, data)
        rows[k] = [data.time, *free_pose(model, data, radius)]
        if stop is not None and stop(rows[k]):
            rows = rows[:k + 1]
            break
    check_healthy(model, data)
    return rows


def incline(model: mujoco.MjModel, slope: float = 0.1, speed: float = 1.0,
            duration: float = 1.0) -> ScenarioResult:
    """Upright disc rolling straight down a slope of ``slope`` rad.

    The incline is a tilted gravity vector ``g (sin β, 0, −cos β)`` over the flat floor
    (the same contact geometry, rotated); the disc starts upright rolling down-slope at
    ``speed`` (above the stability threshold, so it stays upright). The centre's
    down-slope acceleration, from its speed over 50 ms windows, is judged against
    ``g sin β / (1 + C / (m a²))`` over the whole run.
    """
    beta = check_incline(slope)
    v0 = check_rate("speed", speed, "m/s")
    model = _copy(model)
    g = float(np.linalg.norm(model.opt.gravity))
    model.opt.gravity[:] = g * np.array([math.sin(beta), 0.0, -math.cos(beta)])
    data = mujoco.MjData(model)
    disc = disc_from_model(model)
    set_free_state(model, data, disc, disc.initial_state(0.0, v0))
    n = round(duration / model.opt.timestep)
    t = np.empty(n + 1)
    v = np.empty(n + 1)
    for k in range(n + 1):
        if k:
            mujoco.mj_step(model, data)
        t[k], v[k] = data.time, data.qvel[0]
    check_healthy(model, data)
    expected = disc.incline_acceleration(beta)
    w = max(1, round(0.05 / model.opt.timestep))
    acc = (v[w::w] - v[:-w:w]) / (t[w::w] - t[:-w:w])
    err = 100.0 * (acc / expected - 1.0)
    return ScenarioResult("incline", _pair("incline acceleration error", err, "%", 0.5),
                          {"speed": np.column_stack([t, v, v0 + expected * t])})


def stability_sweep(model: mujoco.MjModel, ratios: tuple[float, ...] = (
        0.8, 0.9, 0.95, 1.05, 1.1, 1.2), kick: float = 0.02,
        duration: float = 1.5) -> ScenarioResult:
    """Upright rolling at speeds ``ratio · v_c`` with a lean-rate kick ``θ̇(0) = kick``.

    Linearised (docs/rolling-disc.md) ``θ̈ = λ² θ`` with
    ``λ² = m g a (1 − (v/v_c)²) / (A + m a²)``: the lean grows below ``v_c`` and
    oscillates above. From each run, ``λ²`` is fitted by least squares of
    ``θ̈`` on ``θ`` (while ``|θ| < 0.05`` rad, the linear range); the threshold speed
    measured is where a straight line through the fitted ``λ²`` against ``v²`` crosses
    zero. Judged: that speed against ``v_c`` (2 %), and each run's growth/decay against
    the prediction.
    """
    check_rate("kick", kick, "rad/s")
    disc = disc_from_model(model)
    data = mujoco.MjData(model)
    vc = disc.critical_speed
    lam_sim, lam_an, series = [], [], {}
    for r in ratios:
        v = check_rate("speed ratio", r, "") * vc
        set_free_state(model, data, disc, disc.initial_state(0.0, v, lean_rate=kick))
        rows = _run_free(model, data, duration, disc.radius,
                         stop=lambda row: abs(row[4]) > 0.05)
        t, th, w1 = rows[:, 0], rows[:, 4], rows[:, 5]
        thdd = np.gradient(w1, t)
        lam_sim.append(float(th @ thdd / (th @ th)))
        lam_an.append(disc.lean_rate_squared(v / disc.radius))
        series[f"lean at {r:g} v_c"] = np.column_stack([t, th])
    v2 = (np.asarray(ratios) * vc) ** 2
    slope, icpt = np.polyfit(v2, lam_sim, 1)
    vc_sim = math.sqrt(-icpt / slope) if slope < 0 < icpt else math.nan
    wrong = sum((ls > 0) != (la > 0) for ls, la in zip(lam_sim, lam_an, strict=True))
    mgA = disc.mass * disc.gravity * disc.radius / (disc.diametral_inertia
                                                    + disc.mass * disc.radius**2)
    lam_err = 100.0 * (np.asarray(lam_sim) - lam_an) / mgA
    metrics = (Metric("threshold speed error", 100.0 * abs(vc_sim / vc - 1.0), "%", 2.0,
                      REQUIREMENT),
               Metric("runs growing/decaying against the prediction", float(wrong), "runs",
                      0.0, REQUIREMENT),
               *_pair("lean growth rate λ² error (% of m g a/(A+m a²))", lam_err, "%", 4.0,
                      "derived bound: λ² = m g a (1 − v²/v_c²)/(A + m a²), so 2 % on v_c "
                      "moves λ² by 4 % of m g a/(A + m a²)"))
    series["lambda^2 (v^2, sim, analytic)"] = np.column_stack([v2, lam_sim, lam_an])
    return ScenarioResult("stability sweep", metrics, series)


def steady_precession(model: mujoco.MjModel, lean: float = 0.3, radius: float = 0.6,
                      circles: float = 1.05) -> ScenarioResult:
    """Start exactly on the analytic steady circling and run ``circles`` full circles.

    Judged over the whole run: lean ``θ(t)/θ − 1`` and the contact point's distance
    from the analytic circle centre ``|P(t) − c|/R − 1`` (the circle's radius held, and
    its centre not drifting), in %.
    """
    disc = disc_from_model(model)
    sm = disc.steady_motion(lean, radius)
    positive_circles = check_rate("circles", circles, "")
    data = mujoco.MjData(model)
    set_free_state(model, data, disc, sm.state)
    rows = _run_free(model, data, positive_circles * sm.period, disc.radius)
    centre = np.array([0.0, -radius])
    dist = np.linalg.norm(rows[:, 1:3] - centre, axis=1)
    metrics = (*_pair("precession lean error", 100.0 * (rows[:, 4] / lean - 1.0), "%", 1.0),
               *_pair("precession circle radius error", 100.0 * (dist / radius - 1.0), "%",
                      1.0))
    return ScenarioResult("steady precession", metrics,
                          {"contact path": rows[:, [0, 1, 2]],
                           "lean": rows[:, [0, 4]]})


def _analytic_run(disc: RollingDisc, state: np.ndarray, t: np.ndarray) -> np.ndarray:
    sol = solve_ivp(disc.rhs, (t[0], t[-1]), state, method="DOP853", t_eval=t,
                    rtol=1e-10, atol=1e-12)
    return sol.y.T


def leaning_start(model: mujoco.MjModel, lean: float = 0.15, speed: float = 1.0,
                  duration: float = 5.0) -> ScenarioResult:
    """Leaning rolling start (keyframe ``leaning``) against the nonlinear equations.

    Judged over the whole run: contact point distance ``|P_sim − P_an|`` as % of the
    analytic path length, and lean ``θ_sim − θ_an`` in degrees.
    """
    disc = disc_from_model(model)
    state = disc.initial_state(check_lean(lean), check_rate("speed", speed, "m/s"))
    data = mujoco.MjData(model)
    set_free_state(model, data, disc, state)
    rows = _run_free(model, data, duration, disc.radius)
    ref = _analytic_run(disc, state, rows[:, 0])
    length = float(np.sum(np.linalg.norm(np.diff(ref[:, :2], axis=0), axis=1)))
    path_err = 100.0 * np.linalg.norm(rows[:, 1:3] - ref[:, :2], axis=1) / length
    lean_err = np.degrees(rows[:, 4] - ref[:, 3])
    metrics = (*_pair("leaning start path error (% of path)", path_err, "%", 1.0),
               *_pair("leaning start lean error", lean_err, "deg", 1.0))
    return ScenarioResult("leaning start", metrics, {
        "contact path (t, x, y sim, x, y analytic)": np.column_stack(
            [rows[:, :3], ref[:, :2]]),
        "lean (t, sim, analytic)": np.column_stack([rows[:, 0], rows[:, 4], ref[:, 3]])})


def energy_drift(model: mujoco.MjModel, lean: float = 0.15, speed: float = 1.0,
                 duration: float = 10.0) -> ScenarioResult:
    """Energy of the leaning rolling disc on the flat over ``duration`` s.

    Rolling without slip does no work, so ``E`` must stay ``E_0`` (potential from the
    floor). Judged: ``(E − E_0)/E_0`` in % over the whole run.
    """
    disc = disc_from_model(model)
    state = disc.initial_state(check_lean(lean), check_rate("speed", speed, "m/s"))
    data = mujoco.MjData(model)
    set_free_state(model, data, disc, state)
    rows = _run_free(model, data, duration, disc.radius)
    e = rows[:, 8]
    drift = 100.0 * (e / e[0] - 1.0)
    return ScenarioResult("energy", _pair("energy drift", drift, "%", 0.5),
                          {"energy": rows[:, [0, 8]]})


def free_scenarios(model: mujoco.MjModel) -> list[ScenarioResult]:
    """All free-disc scenarios at their default arguments."""
    return [incline(model), stability_sweep(model), steady_precession(model),
            leaning_start(model), energy_drift(model)]


def _copy(model: mujoco.MjModel) -> mujoco.MjModel:
    return model.__copy__()


# --- the driven wheel on its mount ------------------------------------------------------
def wheel_inertia_from_model(model: mujoco.MjModel, joint: str) -> float:
    """Inertia about a hinge from the compiled model: bodies moving with it + armature.

    ``J = Σ_b (a·I_b a + m_b |r_b⊥|²) + armature`` over the joint's body and its
    subtree (``a`` the joint axis, ``r_b⊥`` the body CoM's offset from the axis).
    """
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    jnt = model.joint(joint)
    jid = jnt.id
    root = int(jnt.bodyid[0])
    axis, anchor = data.xaxis[jid], data.xanchor[jid]
    bodies = [b for b in range(model.nbody) if _in_subtree(model, b, root)]
    total = 0.0
    for b in bodies:
        rot = data.ximat[b].reshape(3, 3)
        inertia = rot @ np.diag(model.body_inertia[b]) @ rot.T
        r = data.xipos[b] - anchor
        r_perp = r - axis * (r @ axis)
        total += axis @ inertia @ axis + model.body_mass[b] * (r_perp @ r_perp)
    return float(total + model.dof_armature[model.jnt_dofadr[jid]])


def _in_subtree(model: mujoco.MjModel, body: int, root: int) -> bool:
    while body > 0:
        if body == root:
            return True
        body = int(model.body_parentid[body])
    return body == root


def mounted_wheel(model: mujoco.MjModel) -> WheelDynamics:
    """Single-wheel model of the mounted disc from the compiled model.

    m: mass of everything the slides carry (carriage subtree); J from
    :func:`wheel_inertia_from_model`; R the collision radius; μ the wheel's friction
    (the floor's is lower priority); N = m g.
    """
    carriage = model.body("carriage").id
    mass = float(model.body_subtreemass[carriage])
    return WheelDynamics(mass=mass, inertia=wheel_inertia_from_model(model, "wheel"),
                         radius=float(model.geom("wheel_collision").size[0]),
                         friction=float(model.geom("wheel_collision").friction[0]),
                         normal_force=mass * float(np.linalg.norm(model.opt.gravity)))


def _mounted_run(model: mujoco.MjModel, torque, duration: float) -> np.ndarray:
    """Torque-mode run; rows ``(t, τ, ẋ, θ̇, contacts)``."""
    model = _copy(model)
    set_actuation_mode(model, "torque")
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    wheel = model.actuator("wheel").id
    vx = model.jnt_dofadr[model.joint("mount_x").id]
    spin = model.jnt_dofadr[model.joint("wheel").id]
    n = round(duration / model.opt.timestep)
    rows = np.empty((n + 1, 5))
    for k in range(n + 1):
        if k:
            mujoco.mj_step(model, data)
        data.ctrl[wheel] = torque(data.time)
        rows[k] = [data.time, data.ctrl[wheel], data.qvel[vx], data.qvel[spin], data.ncon]
    check_healthy(model, data)
    return rows


def slip_onset(model: mujoco.MjModel, ramp: float = 0.25, slip_threshold: float = 0.02,
               ) -> ScenarioResult:
    """Torque ramp ``τ = ramp · t`` on the mounted wheel: the torque where it starts to slip.

    Onset: the first time the slip speed ``R θ̇ − ẋ`` exceeds ``slip_threshold`` m/s.
    Past the true onset the slip grows as ``½ (R/J) ramp (t − t_0)²``, so the detection
    lags by ``Δτ = √(2 ramp J s_th / R)`` (0.5 % of the limit at the defaults), which the
    measured value is corrected by. Judged against ``μ N (J + m R²)/(m R)`` (2 %).
    """
    check_rate("ramp", ramp, "N·m/s")
    w = mounted_wheel(model)
    limit = w.max_rolling_torque
    duration = 1.2 * limit / ramp
    rows = _mounted_run(model, lambda t: ramp * t, duration)
    slip = w.radius * rows[:, 3] - rows[:, 2]
    hit = np.flatnonzero(slip > slip_threshold)
    lag = math.sqrt(2.0 * ramp * w.inertia * slip_threshold / w.radius)
    onset = float(rows[hit[0], 1]) - lag if hit.size else math.nan
    return ScenarioResult("slip onset", (
        Metric("slip onset torque error", 100.0 * abs(onset / limit - 1.0), "%", 2.0,
               REQUIREMENT),), {"slip (t, τ, R θ̇ − ẋ)": np.column_stack(
                   [rows[:, 0], rows[:, 1], slip])})


def slip_pulse(model: mujoco.MjModel, torque_ratio: float = 1.05, on_time: float = 0.3,
               duration: float = 0.8) -> ScenarioResult:
    """Torque pulse ``τ = torque_ratio · τ_max`` for ``on_time`` s on the mounted wheel.

    Judged against :class:`SlipPulse`: the re-grip time (first time after the pulse
    that ``R θ̇ − ẋ`` falls below 1 mm/s); the mean sliding accelerations over each
    phase (change of ``ẋ`` or ``θ̇`` over the phase divided by its length: the friction
    impulse, which the contact's hopping does not disturb as much as a pointwise slope);
    the speed and spin trajectories over the whole run; and the share of sliding steps
    in which the wheel is off the floor. MuJoCo's soft contact couples the normal and the
    friction rows in one cone, and a sliding wheel hops (the wheel is airborne for most
    of the sliding steps): the coast-phase acceleration, measured over a few
    milliseconds of hops, misses its target.
    """
    if not math.isfinite(torque_ratio) or torque_ratio <= 1.0:
        raise ValueError(f"torque_ratio = {torque_ratio!r}; valid range is (1, inf) "
                         f"(above the traction limit)")
    w = mounted_wheel(model)
    pulse = SlipPulse(w, torque_ratio * w.max_rolling_torque, on_time)
    limit = model.actuator_forcerange[model.actuator("wheel").id, 1]
    if pulse.torque > limit:
        raise ValueError(f"torque = {pulse.torque:g} N·m exceeds the motor limit; valid "
                         f"range is ({w.max_rolling_torque:g}, {limit:g}] N·m")
    rows = _mounted_run(model, lambda t: pulse.torque if t < on_time - 1e-9 else 0.0,
                        duration)
    t, speed, spin = rows[:, 0], rows[:, 2], rows[:, 3]
    ref = pulse.state(t)
    tg = pulse.regrip_time

    slip = w.radius * spin - speed
    after = np.flatnonzero((t > on_time) & (slip < 1e-3))
    tg_sim = float(t[after[0]]) if after.size else math.nan
    k1 = int(np.searchsorted(t, on_time - 1e-9))
    kg = int(after[0]) if after.size else len(t) - 1

    def mean_rate(y: np.ndarray, k_lo: int, k_hi: int) -> float:
        return float((y[k_hi] - y[k_lo]) / (t[k_hi] - t[k_lo]))

    acc = [(mean_rate(speed, 0, kg), pulse.linear_acceleration),
           (mean_rate(spin, 0, k1), pulse.spin_acceleration),
           (mean_rate(spin, k1, kg), pulse.coast_spin_acceleration)]
    acc_err = [100.0 * abs(s / e - 1.0) for s, e in acc]
    lost = float(np.mean(rows[1:kg + 1, 4] == 0)) * 100.0
    names = ("ẍ", "θ̈ pulse", "θ̈ coast")
    metrics = [Metric(f"sliding {n} error", e, "%", 2.0, REQUIREMENT)
               for n, e in zip(names, acc_err, strict=True)]
    metrics.append(Metric("re-grip time error", 100.0 * abs(tg_sim / tg - 1.0), "%", 2.0,
                          REQUIREMENT))
    metrics.append(Metric("steps without contact while sliding", lost, "%", 0.0,
                          "derived bound: the wheel carries its weight, so it must stay "
                          "on the floor"))
    speed_scale = pulse.linear_acceleration * tg
    metrics += _pair("speed error (% of peak speed)", 100.0 * (speed - ref[:, 1])
                     / speed_scale, "%", 2.0, "derived bound: the 2 % on accelerations")
    metrics += _pair("spin error (% of peak spin)", 100.0 * (spin - ref[:, 2])
                     / np.abs(ref[:, 2]).max(), "%", 2.0,
                     "derived bound: the 2 % on accelerations")
    return ScenarioResult("slip pulse", tuple(metrics), {
        "speed (t, sim, closed form)": np.column_stack([t, speed, ref[:, 1]]),
        "spin (t, sim, closed form)": np.column_stack([t, spin, ref[:, 2]])})


def mounted_scenarios(model: mujoco.MjModel) -> list[ScenarioResult]:
    """The driven-wheel scenarios at their default arguments."""
    return [slip_onset(model), slip_pulse(model)]


def metric_rows(results: list[ScenarioResult]) -> list[tuple[str, str, float, str, float,
                                                             str, bool]]:
    """Flat rows ``(scenario, metric, value, unit, target, basis, passed)``."""
    return [(r.name, *m.row(), m.passed) for r in results for m in r.metrics]
