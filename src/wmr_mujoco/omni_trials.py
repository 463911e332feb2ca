"""Open-loop trials of omni-wheeled models against ideal omni kinematics.

A trial commands a constant body twist ν (reached by a linear ramp) as wheel rates
``θ̇ = H ν`` from the ideal kinematics, runs MuJoCo from a settled start, and compares the
pose with the same ramped twist integrated analytically (:mod:`wmr_mujoco.analytic`).
It works on any MuJoCo model whose wheels are hinges on a free-floating base: the wheel
layout is read from the compiled model (:func:`layout_from_model`), so the same trial
runs on this package's ``omni3`` and on a peer model.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.analytic import omni_kinematics as ok
from wmr_mujoco.analytic.integrate import integrate
from wmr_mujoco.scenarios import OMNI_DIRECTIONS_DEG, OMNI_SPEED, OMNI_YAW_RATE
from wmr_mujoco.simulation import check_healthy


@dataclass(frozen=True)
class OmniTrial:
    """A body twist held for ``duration`` after a linear ramp of ``ramp`` seconds.

    Attributes:
        name: label.
        twist: ``(u, v, r)`` body-frame target, m/s and rad/s.
        duration: seconds from the start of the ramp to the end.
        ramp: seconds of the linear ramp from rest (keeps traction below the limit).
        settle: seconds at rest before the ramp.
    """

    name: str
    twist: tuple[float, float, float]
    duration: float = 5.0
    ramp: float = 0.5
    settle: float = 0.5

    def twist_at(self, t: float) -> np.ndarray:
        """Commanded twist ``t`` seconds after the start of the ramp."""
        return np.asarray(self.twist, float) * float(np.clip(t / self.ramp, 0.0, 1.0))


def standard_trials(speed: float = OMNI_SPEED, yaw_rate: float = OMNI_YAW_RATE
                    ) -> list[OmniTrial]:
    """Translations in 8 directions, pure rotation, and two translation+rotation trials.

    The manoeuvres of the omni validation scenarios (:mod:`wmr_mujoco.scenarios`), held
    for 5 s instead of 10, plus a diagonal translation with rotation.
    """
    trials = [OmniTrial(f"translate {deg:>3d}°", (speed * np.cos(np.radians(deg)),
                                                  speed * np.sin(np.radians(deg)), 0.0))
              for deg in OMNI_DIRECTIONS_DEG]
    trials.append(OmniTrial("rotate", (0.0, 0.0, yaw_rate)))
    trials.append(OmniTrial("translate+rotate", (speed, 0.0, 0.5 * yaw_rate)))
    trials.append(OmniTrial("diagonal+rotate", (-0.6 * speed, 0.6 * speed, -yaw_rate)))
    return trials


@dataclass(frozen=True)
class OmniModelInfo:
    """What a trial needs to know about a model.

    Attributes:
        layout: wheel layout in the base frame, from the compiled model.
        wheel_joints: joint ids of the wheels, in layout order.
        wheel_actuators: actuator id driving each wheel.
        angle_servo: per wheel, True if the actuator takes a target angle (position
            servo) rather than a rate.
        base_body: id of the free-floating base body.
    """

    layout: ok.WheelLayout
    wheel_joints: tuple[int, ...]
    wheel_actuators: tuple[int, ...]
    angle_servo: tuple[bool, ...]
    base_body: int


def layout_from_model(model: mujoco.MjModel, wheel_joints: Sequence[str]) -> OmniModelInfo:
    """Read the wheel layout of a settled model from its geometry.

    For each wheel hinge with world axis ``a`` and centre ``c`` (relative to the base),
    the drive direction is ``a × ẑ`` (a positive rate rolls the centre that way) and the
    radius is the centre's height above the floor at rest.
    """
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    for _ in range(int(0.5 / model.opt.timestep)):  # settle on the floor
        mujoco.mj_step(model, data)
    mujoco.mj_forward(model, data)
    joint_ids = [model.joint(j).id for j in wheel_joints]
    base = int(model.jnt_bodyid[joint_ids[0]])
    while model.body_parentid[base] != 0:
        base = int(model.body_parentid[base])
    base_rot = data.xmat[base].reshape(3, 3)
    pos, beta, radii, acts, angle = [], [], [], [], []
    for j in joint_ids:
        axis = data.xaxis[j]
        centre = data.xanchor[j]
        drive = np.cross(axis, [0.0, 0.0, 1.0])
        drive_b = base_rot.T @ drive
        rel_b = base_rot.T @ (centre - data.xpos[base])
        pos.append(rel_b[:2])
        beta.append(np.arctan2(drive_b[1], drive_b[0]))
        radii.append(centre[2] / np.linalg.norm(drive))
        act = [a for a in range(model.nu) if model.actuator_trnid[a, 0] == j
               and model.actuator_trntype[a] == mujoco.mjtTrn.mjTRN_JOINT]
        if len(act) != 1:
            raise ValueError(f"wheel joint {model.joint(j).name!r} has {len(act)} actuators; "
                             f"expected exactly one")
        acts.append(act[0])
        angle.append(bool(model.actuator_biasprm[act[0], 1] != 0.0
                          and model.actuator_dyntype[act[0]] == mujoco.mjtDyn.mjDYN_NONE))
    layout = ok.WheelLayout(np.asarray(pos), np.asarray(beta), np.zeros(len(pos)),
                            np.asarray(radii))
    return OmniModelInfo(layout, tuple(joint_ids), tuple(acts), tuple(angle), base)


@dataclass(frozen=True)
class TrialResult:
    """Measured outcome of one trial.

    Attributes:
        name: trial label.
        path: analytic path length of the base origin, m.
        position_error: final distance between simulated and analytic base origin, m.
        heading_error: final simulated minus analytic heading, degrees.
        turned: analytic heading change, degrees.
        yaw_rate_ripple: std of the yaw rate over the steady phase / |commanded rate|
            (NaN without rotation).
        roller_rate_error: median relative error of contacting rollers' spin rates against
            slide speed / contact radius implied by the commanded twist (NaN if none
            slides).
        real_time_factor: simulated seconds per wall-clock second of ``mj_step``.
    """

    name: str
    path: float
    position_error: float
    heading_error: float
    turned: float
    yaw_rate_ripple: float
    roller_rate_error: float
    real_time_factor: float

    @property
    def position_error_pct(self) -> float:
        """Position error as a percentage of path (NaN for a path under 1 mm)."""
        return 100.0 * self.position_error / self.path if self.path > 1e-3 else float("nan")


def _yaw(xmat: np.ndarray) -> float:
    return float(np.arctan2(xmat[3], xmat[0]))


def roller_rate_errors(model: mujoco.MjModel, data: mujoco.MjData, info: OmniModelInfo,
                        twist_world_slide: np.ndarray) -> list[float]:
    """Relative errors |ω_r| vs |slide|/ρ for the rollers touching the floor now."""
    errors = []
    wheel_bodies = {int(model.jnt_bodyid[j]): i for i, j in enumerate(info.wheel_joints)}
    for c in data.contact[:data.ncon]:
        geom = c.geom2 if model.geom_bodyid[c.geom1] == 0 else c.geom1
        body = int(model.geom_bodyid[geom])
        parent = int(model.body_parentid[body])
        if parent not in wheel_bodies or model.body_jntnum[body] != 1:
            continue
        jnt = int(model.body_jntadr[body])
        axis = data.xaxis[jnt]
        rel = c.pos - data.xanchor[jnt]
        rho = np.linalg.norm(rel - axis * (rel @ axis))
        slide = abs(twist_world_slide[wheel_bodies[parent]])
        if slide < 1e-3 or rho < 1e-6:
            continue
        omega = abs(data.qvel[model.jnt_dofadr[jnt]])
        errors.append(abs(omega * rho - slide) / slide)
    return errors


def run_trial(model: mujoco.MjModel, info: OmniModelInfo, trial: OmniTrial) -> TrialResult:
    """Run ``trial`` on ``model`` (driven open loop) and against the analytic twist.

    Raises:
        SimulationDivergedError: the simulation produced NaN or MuJoCo warnings.
    """
    data = mujoco.MjData(model)
    H = ok.wheel_jacobian(info.layout)
    dt = model.opt.timestep
    acts = np.asarray(info.wheel_actuators)
    angle_servo = np.asarray(info.angle_servo)
    qadr = np.asarray([model.jnt_qposadr[j] for j in info.wheel_joints])
    for _ in range(round(trial.settle / dt)):
        data.ctrl[acts] = np.where(angle_servo, data.qpos[qadr], 0.0)
        mujoco.mj_step(model, data)
    check_healthy(model, data)
    base = info.base_body
    start = np.array([*data.xpos[base][:2], _yaw(data.xmat[base])])
    target_angle = data.qpos[qadr].copy()
    nstep = round(trial.duration / dt)
    twists = np.array([trial.twist_at(k * dt) for k in range(nstep)])
    yaw_rates, roller_errors = [], []
    wall = 0.0
    for k in range(nstep):
        rates = H @ twists[k]
        target_angle += rates * dt
        data.ctrl[acts] = np.where(angle_servo, target_angle, rates)
        t0 = time.perf_counter()
        mujoco.mj_step(model, data)
        wall += time.perf_counter() - t0
        if k * dt >= trial.ramp + 0.5:  # steady phase
            yaw_rates.append(data.cvel[base][2])
            if k % 10 == 0:
                slide = ok.roller_slide_speeds(info.layout, twists[k])
                roller_errors += roller_rate_errors(model, data, info, slide)
    check_healthy(model, data)
    analytic = integrate(lambda x, nu: ok.body_to_world(x[2], nu), start, twists, dt)
    end = np.array([*data.xpos[base][:2], _yaw(data.xmat[base])])
    heading_err = float(np.degrees(np.angle(np.exp(1j * (end[2] - analytic[-1, 2])))))
    path = float(np.sum(np.linalg.norm(np.diff(analytic[:, :2], axis=0), axis=1)))
    yaw_cmd = abs(trial.twist[2])
    ripple = float(np.std(yaw_rates) / yaw_cmd) if yaw_cmd > 0 and yaw_rates else float("nan")
    return TrialResult(
        name=trial.name, path=path,
        position_error=float(np.linalg.norm(end[:2] - analytic[-1, :2])),
        heading_error=heading_err,
        turned=float(np.degrees(analytic[-1, 2] - analytic[0, 2])),
        yaw_rate_ripple=ripple,
        roller_rate_error=float(np.median(roller_errors)) if roller_errors else float("nan"),
        real_time_factor=trial.duration / wall if wall > 0 else float("nan"))


def rolling_radius_profile(model: mujoco.MjModel, wheel_joint: str, roller_prefix: str,
                           samples: int = 721) -> np.ndarray:
    """Distance from the wheel axle to the floor-touching point over one revolution.

    Measured on the model's own collision geometry with ``mj_geomDistance`` between the
    floor and every roller geom (named ``roller_prefix...``), with the wheel axle held
    horizontal at a fixed height and the wheel turned through 360°.

    Returns:
        (samples,) rolling radius at wheel angles ``linspace(0, 2π, samples)``.
    """
    data = mujoco.MjData(model)
    floor = model.geom("floor").id
    jid = model.joint(wheel_joint).id
    geoms = [g for g in range(model.ngeom)
             if (model.geom(g).name or "").startswith(roller_prefix)
             and model.geom_contype[g] | model.geom_conaffinity[g]]
    if not geoms:
        raise ValueError(f"no collision geoms named {roller_prefix!r}* in the model")
    fromto = np.zeros(6)
    out = np.empty(samples)
    for i, angle in enumerate(np.linspace(0.0, 2.0 * np.pi, samples)):
        data.qpos[:] = model.qpos0
        data.qpos[2] += 0.5  # lift the free base clear of the floor
        data.qpos[model.jnt_qposadr[jid]] = angle
        mujoco.mj_kinematics(model, data)
        gap = min(mujoco.mj_geomDistance(model, data, g, floor, 2.0, fromto) for g in geoms)
        out[i] = data.xanchor[jid][2] - gap
    return out
