"""omni3's dynamic runs: the physics and the hybrid model on the same inputs, all at once.

Every dynamic scenario of omni3 (step commands, torque inputs, coasting) is one
:class:`RunSpec`. :func:`dynamic_runs` simulates all of them together: the physics in two
batched, threaded ``mujoco.rollout`` calls (one per actuation mode, each from its own
settled start) plus one for the coasts, and the hybrid model
(:func:`~wmr_mujoco.robots.roller_wheels.omni_hybrid.simulate_batch`) in one vectorised
integration of every run. The result is cached per parameter set, so the scenarios that read it
share
one simulation.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.analytic.planar import wrap_angle
from wmr_mujoco.models.actuation import ActuationMode, set_actuation_mode
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.physics import (  # noqa: F401  (contact readers re-exported)
    WHEELS,
    contact_wheels,
    rollout_from,
    settle_at_phases,
    wheels_off_floor,
)
from wmr_mujoco.robots.roller_wheels import drive_from_model, hybrid_from_model, roller_rates
from wmr_mujoco.robots.roller_wheels import omni_hybrid as oh
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.sim.stepping import check_healthy

#: The body the platform's yaw inertia is taken about.
CENTRE_BODY = "platform"
#: Seconds from a run's start over which the wheels' floor contacts are read
#: (:attr:`Run.off_floor`): a step command's start-up, where sliding wheels can lift.
CONTACT_WINDOW = 0.1
#: Seconds at rest before a run (as the runner's scenarios).
SETTLE = 0.5
#: Longest RK4 step of the hybrid model, s: at the default simulation step (1.25 ms) the model
#: takes one RK4 step per simulation step (it reports on the physics' grid). The rate
#: servo is stiff (k_v / I_w ≈ 480 /s), well inside RK4's stability bound (≈ 2.8 / 480 s)
#: at 2 ms; measured at the earlier 4 ms simulation step, the worst step-command figure
#: moved from 0.27 % of path at a 2 ms RK4 step to 0.15 % at 1 ms and 0.09 % at 0.5 ms,
#: the torque and coasting figures by under 0.02 and 1 point.
HYBRID_STEP = 0.002


@dataclass(frozen=True)
class RunSpec:
    """One dynamic run.

    Attributes:
        name: label (unique).
        mode: actuation during the judged phase (rate servo or torque).
        command: constant wheel rates (rad/s, rate mode) or torques (N·m), held from rest
            (a step: no ramp).
        duration: judged phase, s.
        lead_in: body twist driven (rate servo, linear ramp over ``lead_ramp``) for
            ``lead_time`` before the judged phase (a coast's drive), or None: the run
            starts at rest.
        lead_time: s.
        phase: every wheel's angle at the start, rad (the robot settles at rest on it,
            the wheels held by the rate servo: :func:`~.physics.settle_at_phases`).
        lead_ramp: the lead-in's ramp time, s (0: a step).
    """

    name: str
    mode: ActuationMode
    command: tuple[float, float, float]
    duration: float
    lead_in: tuple[float, float, float] | None = None
    lead_time: float = 0.0
    phase: float = 0.0
    lead_ramp: float = 0.5

    def __post_init__(self) -> None:
        for label, vec in (("command", self.command), ("lead_in", self.lead_in or (0,) * 3)):
            arr = np.asarray(vec, float)
            if arr.shape != (3,) or not np.all(np.isfinite(arr)):
                raise ValueError(f"{self.name}: {label} = {vec!r}; needs 3 finite numbers")
        for label, value, low in (("duration", self.duration, 0.0),
                                  ("lead_time", self.lead_time, -1.0),
                                  ("lead_ramp", self.lead_ramp, -1.0)):
            if not (math.isfinite(value) and low < value <= 30.0):
                raise ValueError(f"{self.name}: {label} = {value!r} s; valid range is "
                                 f"({max(low, 0.0):g}, 30] s")
        if not (math.isfinite(self.phase) and abs(self.phase) <= 2 * math.pi):
            raise ValueError(f"{self.name}: phase = {self.phase!r} rad; valid range is "
                             "[-2π, 2π]")


@dataclass(frozen=True)
class Run:
    """One run through the physics and the hybrid model, from the same measured start.

    Attributes:
        spec: the run.
        t: (N + 1,) times from the start of the judged phase, s.
        pose: (N + 1, 3) physics pose in the start frame (X, Y, ψ), ψ unwrapped.
        twist: (N + 1, 3) physics body twist (u, v, r).
        wheel_angles, wheel_rates: (N + 1, 3) physics wheel hinges.
        hybrid: the hybrid model's run.
        dt: simulation step, s.
        off_floor: (K, 3) per sample of the first :data:`CONTACT_WINDOW` s, whether each
            wheel has no roller touching the floor (:func:`wheels_off_floor`).
    """

    spec: RunSpec
    t: np.ndarray
    pose: np.ndarray
    twist: np.ndarray
    wheel_angles: np.ndarray
    wheel_rates: np.ndarray
    hybrid: oh.HybridRun
    dt: float
    off_floor: np.ndarray


def phase_lag_steps(run: Run) -> float:
    """The hybrid model's worst wheel phase against the physics', in steps' turns, signed.

    ``(θ_model − θ_physics) / |θ_physics,k+1 − θ_physics,k|`` at the wheel and sample
    where its magnitude is largest, over the samples whose turn per step is at least a
    tenth of the run's largest (negative: the model's wheels behind; how many samples a
    hand-over of the model falls from the physics'; 0 for a run that does not turn its
    wheels).
    """
    turn = np.abs(np.diff(run.wheel_angles, axis=0))
    if not turn.size or turn.max() <= 0:
        return 0.0
    fast = turn >= 0.1 * turn.max()
    ratio = np.where(fast, (run.hybrid.thetas - run.wheel_angles)[:-1]
                     / np.where(fast, turn, 1.0), 0.0)
    return float(ratio.flat[np.argmax(np.abs(ratio))])


def settled(mode: ActuationMode, params: OmniParams | None = None,
            timestep: float | None = None) -> tuple[mujoco.MjModel, mujoco.MjData]:
    """omni3 in ``mode``, settled at rest on the floor for :data:`SETTLE` s.

    ``timestep``: simulation step, s (None: the model's own); a finer one is the time-step
    convergence study of ``docs/omni-dynamics.md``.

    Raises:
        ValueError: a timestep outside (0, 0.01] s.
    """
    from wmr_mujoco.models.loading import load
    from wmr_mujoco.robots.omni3 import SPEC  # the entry imports this module

    if timestep is not None and not (math.isfinite(timestep) and 0 < timestep <= 0.01):
        raise ValueError(f"timestep = {timestep!r} s; valid range is (0, 0.01] s")
    model = load(SPEC, params)
    if timestep is not None:
        model.opt.timestep = timestep
    set_actuation_mode(model, mode)
    data = mujoco.MjData(model)
    for _ in range(round(SETTLE / model.opt.timestep)):
        mujoco.mj_step(model, data)
    check_healthy(model, data)
    mujoco.mj_forward(model, data)
    return model, data


def coast_start(twist: Sequence[float], drive_time: float,
                setup: Callable[[mujoco.MjModel], None] | None = None,
                params: OmniParams | None = None) -> tuple[mujoco.MjModel, mujoco.MjData]:
    """omni3 settled, driven at ``twist`` for ``drive_time`` s, then its motors off.

    The drive is the rate servo on ``H ν · min(1, t / 0.5 s)``; at motor-off the robot is
    switched to torque mode with zero torque, so what follows is a coast. ``params``
    (None: the defaults) builds the model; ``setup`` changes the settled model before
    the drive (e.g. an enable flag).

    Raises:
        ValueError: a twist that is not 3 finite numbers, or a drive time outside
            (0, 30] s.
    """
    nu = np.asarray(twist, float)
    if nu.shape != (3,) or not np.all(np.isfinite(nu)):
        raise ValueError(f"twist = {twist!r}; needs 3 finite numbers")
    if not (math.isfinite(drive_time) and 0 < drive_time <= 30):
        raise ValueError(f"drive_time = {drive_time!r} s; valid range is (0, 30] s")
    model, data = settled(ActuationMode.RATE, params)
    if setup is not None:
        setup(model)
    hy = hybrid(params)
    dt = model.opt.timestep
    H = ok.wheel_jacobian(ok.symmetric_layout(hy.radius, hy.distance))
    for k in range(round(drive_time / dt)):
        data.ctrl[:] = min(1.0, k * dt / 0.5) * (H @ nu)
        mujoco.mj_step(model, data)
    set_actuation_mode(model, ActuationMode.TORQUE)
    data.ctrl[:] = 0.0
    mujoco.mj_forward(model, data)
    return model, data


def base_states(model: mujoco.MjModel, states: np.ndarray
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """World pose, body twist, wheel angles and rates from full-physics states (N, ·).

    The ``base`` site is the platform's origin (checked): with the free joint's
    ``(p, q)`` and ``(v_world, ω_body)``, ``ψ = atan2(R₁₀, R₀₀)`` and
    ``(u, v) = (Rᵀ v_world)_xy``, ``r = ω_body,z`` (what ``mj_objectVelocity`` gives).
    """
    site = model.site("base").id
    if model.site_bodyid[site] != 1 or np.any(model.site_pos[site]) or not np.allclose(
            model.site_quat[site], [1, 0, 0, 0]):
        raise ValueError("the base site is not the free body's origin")
    nq = model.nq
    qpos, qvel = states[:, 1:1 + nq], states[:, 1 + nq:1 + nq + model.nv]
    w, x, y, z = qpos[:, 3], qpos[:, 4], qpos[:, 5], qpos[:, 6]
    r00, r10, r20 = 1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)
    r01, r11, r21 = 2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)
    vw = qvel[:, :3]
    u = r00 * vw[:, 0] + r10 * vw[:, 1] + r20 * vw[:, 2]
    v = r01 * vw[:, 0] + r11 * vw[:, 1] + r21 * vw[:, 2]
    pose = np.column_stack([qpos[:, 0], qpos[:, 1], np.arctan2(r10, r00)])
    twist = np.column_stack([u, v, qvel[:, 5]])
    jq = [model.jnt_qposadr[model.joint(wh).id] for wh in WHEELS]
    jv = [model.jnt_dofadr[model.joint(wh).id] for wh in WHEELS]
    return pose, twist, qpos[:, jq], qvel[:, jv]


def relative(pose: np.ndarray, start: np.ndarray) -> np.ndarray:
    """Pose in the start frame (every model starts at the origin, heading 0), ψ unwrapped."""
    d = pose[:, :2] - start[:2]
    c, s = math.cos(start[2]), math.sin(start[2])
    heading = np.unwrap(wrap_angle(pose[:, 2] - start[2]))
    return np.column_stack([c * d[:, 0] + s * d[:, 1], -s * d[:, 0] + c * d[:, 1], heading])


def _ramp(twist: Sequence[float], hy: oh.OmniHybrid, n: int, dt: float,
          ramp: float = 0.5) -> np.ndarray:
    """Wheel rates ``H ν · min(1, t / ramp)`` over n steps (ramp 0: a step)."""
    H = ok.wheel_jacobian(ok.symmetric_layout(hy.radius, hy.distance))
    share = np.clip(np.arange(n) * dt / ramp, 0.0, 1.0) if ramp > 0 else np.ones(n)
    return share[:, None] * (H @ np.asarray(twist))


#: Most runs of one rollout call: a batch's states (~3 MB a run) are reduced to what the
#: runs keep (:func:`physics_states`) before the next chunk is simulated.
CHUNK = 40


def _chunks(items: list, size: int = CHUNK) -> list[list]:
    return [items[k:k + size] for k in range(0, len(items), size)]


def physics_states(specs: Sequence[RunSpec], models: dict[ActuationMode, mujoco.MjModel],
                   hy: oh.OmniHybrid, keep: Callable[[RunSpec, np.ndarray], object]
                   ) -> dict[str, object]:
    """Every run's full-physics states, reduced by ``keep(spec, states)`` chunk by chunk.

    Settled at each spec's phase (rate servo holding the wheels, :data:`SETTLE` s); then
    the runs from rest and the lead-ins (rate servo on the ramped twist), in threaded
    batches of at most :data:`CHUNK` runs per mode; then, from each lead-in's end, the
    judged phase in the spec's mode.
    """
    rate = models[ActuationMode.RATE]
    dt = rate.opt.timestep
    limit = float(rate.actuator(WHEELS[0]).ctrlrange[1])
    phases = sorted({s.phase for s in specs})
    rest = dict(zip(phases, settle_at_phases(rate, WHEELS, phases, SETTLE), strict=True))
    first: dict[ActuationMode, list[tuple[RunSpec, np.ndarray]]] = {m: [] for m in ActuationMode}
    for s in specs:
        if s.mode is ActuationMode.RATE and np.any(np.abs(s.command) > limit):
            raise ValueError(f"{s.name}: wheel rates {s.command} beyond the rate limit "
                             f"±{limit:g} rad/s")
        if s.lead_in is not None:
            first[ActuationMode.RATE].append((s, _ramp(
                s.lead_in, hy, round(s.lead_time / dt), dt, s.lead_ramp)))
        else:
            first[s.mode].append((s, np.tile(np.asarray(s.command, float),
                                             (round(s.duration / dt), 1))))
    out: dict[str, object] = {}
    lead_end: dict[str, np.ndarray] = {}
    for mode, group in first.items():
        for chunk in _chunks(group):
            trajs = rollout_from(models[mode], np.array([rest[g[0].phase] for g in chunk]),
                                 [g[1] for g in chunk])
            for (spec, _), traj in zip(chunk, trajs, strict=True):
                if spec.lead_in is not None:
                    lead_end[spec.name] = traj[-1]
                else:
                    out[spec.name] = keep(spec, traj)
    for mode in ActuationMode:
        for chunk in _chunks([s for s in specs if s.lead_in is not None and s.mode is mode]):
            trajs = rollout_from(models[mode], np.array([lead_end[s.name] for s in chunk]),
                                 [np.tile(np.asarray(s.command, float),
                                          (round(s.duration / dt), 1)) for s in chunk])
            out.update({s.name: keep(s, t) for s, t in zip(chunk, trajs, strict=True)})
    return out


def simulate_runs(specs: Sequence[RunSpec], params: OmniParams | None = None,
                  timestep: float | None = None, arc: bool = True,
                  relax: bool = True, turning: bool = True) -> dict[str, Run]:
    """Every run through the physics (batched rollouts) and the hybrid model (one batch).

    ``timestep``: the physics' step (None: the model's own, as ``wmr validate``); the
    hybrid model reports on the same grid, in RK4 steps of at most :data:`HYBRID_STEP`.
    ``arc``: the hybrid model with the weight's moment over the roller arc
    (:func:`~wmr_mujoco.robots.roller_wheels.omni_hybrid.simulate_batch`; on in ``wmr validate``).
    ``relax``: each hand-over's jump spread as the soft contact makes it at the physics'
    step (:attr:`~wmr_mujoco.robots.roller_wheels.omni_hybrid.OmniHybrid.handover_relaxation`;
    on in ``wmr validate``); off: made at once (the rigid impact map). ``turning``: the
    hand-over overlap's duration with the wheel's acceleration, and the normal loads at
    the contact points with the heave (on in ``wmr validate``; off: the model before
    issue 24).

    Raises:
        ValueError: duplicate names, a command beyond the actuators' range, or a bad
            timestep.
        SimulationDivergedError: the physics diverged.
        FloatingPointError: the hybrid model diverged.
    """
    names = [s.name for s in specs]
    if len(set(names)) != len(names):
        raise ValueError(f"run names must be unique: {names}")
    models = {m: settled(m, params, timestep) for m in ActuationMode}
    hy = hybrid(params) if timestep is None else _read(models[ActuationMode.TORQUE][0], params)
    dt = models[ActuationMode.TORQUE][0].opt.timestep
    model = models[ActuationMode.TORQUE][0]
    window = round(CONTACT_WINDOW / dt) + 1

    def keep(spec: RunSpec, states: np.ndarray) -> tuple:
        pose, twist, th, rates = base_states(model, states)
        return ((relative(pose, pose[0]), twist, th, rates), states[0],
                wheels_off_floor(model, states[:window], WHEELS))

    kept = physics_states(specs, {m: mm for m, (mm, _) in models.items()}, hy, keep)
    phys = {name: k[0] for name, k in kept.items()}  # type: ignore[index]
    starts = {name: k[1] for name, k in kept.items()}  # type: ignore[index]
    # 3. The hybrid model, every run in one batch from the measured starts.
    nmax = max(len(phys[s.name][0]) - 1 for s in specs)
    inputs = np.zeros((len(specs), nmax, 3))
    for b, s in enumerate(specs):
        inputs[b] = np.asarray(s.command, float)
    drives = [drive_from_model(models[s.mode][0], WHEELS[0], s.mode) for s in specs]
    runs = oh.simulate_batch(
        hy, drives, inputs, dt, np.zeros((len(specs), 3)),
        np.array([phys[s.name][1][0] for s in specs]),
        np.array([phys[s.name][2][0] for s in specs]),
        np.array([roller_rates(model, starts[s.name][1 + model.nq:], WHEELS)
                  for s in specs]), substeps=max(1, math.ceil(dt / HYBRID_STEP - 1e-9)), arc=arc,
        relax=hy.handover_relaxation if relax else 0.0, turning=turning, heave=turning)
    out = {}
    for s, run in zip(specs, runs, strict=True):
        pose, twist, th, rates = phys[s.name]
        n = len(pose)
        cut = oh.HybridRun(run.t[:n], run.pose[:n], run.twist[:n], run.thetas[:n],
                           run.torques[:n], [w for w in run.switches if w[0] <= run.t[n - 1]])
        out[s.name] = Run(s, cut.t, pose, twist, th, rates, cut, dt,
                          kept[s.name][2])  # type: ignore[index]
    return out


@functools.lru_cache(maxsize=4)
def cached_runs(specs: tuple[RunSpec, ...], params: OmniParams | None = None
                ) -> dict[str, Run]:
    """:func:`simulate_runs`, once per (specs, params): the scenarios share it."""
    return simulate_runs(specs, params)


def hybrid(params: OmniParams | None = None) -> oh.OmniHybrid:
    """The hybrid model of omni3 (default: the checked-in model)."""
    return _hybrid(params)


@functools.lru_cache(maxsize=4)
def _hybrid(params: OmniParams | None) -> oh.OmniHybrid:
    from wmr_mujoco.models.loading import load
    from wmr_mujoco.robots.omni3 import SPEC  # the entry imports this module

    return _read(load(SPEC, params), params)


def hybrid_at(timestep: float, params: OmniParams | None = None) -> oh.OmniHybrid:
    """The hybrid model of omni3 simulated at ``timestep``.

    Its hand-over relaxation ρ depends on the step; everything else is the model's own.
    """
    return _read(settled(ActuationMode.TORQUE, params, timestep)[0], params)


def _read(model: mujoco.MjModel, params: OmniParams | None) -> oh.OmniHybrid:
    """:func:`~wmr_mujoco.robots.roller_wheels.hybrid_from_model` of omni3."""
    p = params or OmniParams()
    return hybrid_from_model(model, ok.symmetric_layout(p.wheel_radius, p.wheel_distance),
                             CENTRE_BODY, WHEELS)
