"""One manoeuvre in MuJoCo beside the ideal kinematic model, recorded for the figures.

Sequence: reset; ``SETTLE`` s with the wheels held (steering turned to its angles);
the manoeuvre's twist ramped in linearly over ``RAMP`` s and held to ``duration``; then
``COAST`` s with the actuators disabled (MuJoCo's ``mjDSBL_ACTUATION``), the robot rolling
free, for the energy check. The ideal model integrates the same ramped twist from the
settled pose: ``ẋ = Rot(ψ)(u, v)``, ``ψ̇ = r`` (midpoint rule at the physics step).
"""

from __future__ import annotations

import copy
import time
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.audit.drive import Drive
from wmr_mujoco.audit.kinematics import Manoeuvre, contact_velocity, steer_angle, wheel_row
from wmr_mujoco.audit.wheels import Wheels
from wmr_mujoco.models.colliders import colliders
from wmr_mujoco.sim.stepping import SimulationDivergedError

SETTLE = 0.5
RAMP = 0.2
COAST = 0.5
#: Recording period, s.
SAMPLE = 0.005


@dataclass
class Record:
    """Samples of one run (``k`` samples of the drive, ``m`` of the coast, ``w`` wheels).

    Attributes:
        time: (k,) s since the manoeuvre began.
        sim: (k, 3) reference point x, y and heading (MuJoCo).
        ideal: (k, 3) the same for the ideal model.
        height: (k, w) wheel axle height above the floor, m.
        slip: (k, w) slip speed along each wheel's constrained direction, m/s.
        on_floor: (k, w) whether each wheel touches the floor.
        depth: deepest penetration into the floor, m.
        energy: (m,) total energy over the coast, J.
        kinetic0: kinetic energy when the coast began, J.
        wall: wall-clock seconds of the stepping.
        simulated: simulated seconds.
        wheel_speed: largest commanded wheel ground speed, m/s.
    """

    time: np.ndarray
    sim: np.ndarray
    ideal: np.ndarray
    height: np.ndarray
    slip: np.ndarray
    on_floor: np.ndarray
    depth: float
    energy: np.ndarray
    kinetic0: float
    wall: float
    simulated: float
    wheel_speed: float


def _heading(data: mujoco.MjData, body: int) -> float:
    x = data.xmat[body].reshape(3, 3)[:, 0]
    return float(np.arctan2(x[1], x[0]))


class _Probe:
    """Reads the reference point, wheel heights, slips and floor contacts."""

    def __init__(self, model: mujoco.MjModel, found: Wheels, ref: np.ndarray) -> None:
        self.model, self.found, self.ref = model, found, ref
        self.floor = {g for g in colliders(model) if model.geom_bodyid[g] == 0}
        self.geoms = [set(w.geoms) for w in found.wheels]
        self.floor_z = max((float(model.geom_pos[g][2]) for g in self.floor), default=0.0)
        self.depth = 0.0

    def pose(self, data: mujoco.MjData) -> np.ndarray:
        b = self.found.chassis
        rot = data.xmat[b].reshape(3, 3)
        p = data.xpos[b] + rot @ np.array([self.ref[0], self.ref[1], 0.0])
        return np.array([p[0], p[1], _heading(data, b)])

    def contacts(self, data: mujoco.MjData) -> list[bool]:
        touching: set[int] = set()
        for i in range(data.ncon):
            g1, g2 = int(data.contact.geom[i, 0]), int(data.contact.geom[i, 1])
            if g1 in self.floor or g2 in self.floor:
                touching.add(g2 if g1 in self.floor else g1)
                self.depth = max(self.depth, -float(data.contact.dist[i]))
        return [bool(gs & touching) for gs in self.geoms]

    def slips(self, data: mujoco.MjData, prev: np.ndarray, dt: float) -> np.ndarray:
        """Slip of each wheel along its constrained direction.

        From the axle points' finite-difference velocity (the constrained directions of
        :mod:`~wmr_mujoco.audit.kinematics`).
        """
        out = np.zeros(len(self.found.wheels))
        for i, w in enumerate(self.found.wheels):
            if w.kind == "ball":
                continue
            vc = (data.xanchor[w.joint] - prev[i]) / dt
            n = data.xaxis[w.joint].copy()
            n[2] = 0.0
            n /= max(np.linalg.norm(n), 1e-12)
            if w.kind == "swedish":
                s = np.cross([0.0, 0.0, 1.0], n)
                g = w.wheel.roller_angle or 0.0
                e = np.cos(g) * s + np.sin(g) * n
                omega = data.qvel[self.model.jnt_dofadr[w.joint]]
                out[i] = e @ (vc + omega * w.radius * s)
            else:
                out[i] = n @ vc
        return out


def _command(drive: Drive, data: mujoco.MjData, rates: dict[str, float],
             steer: dict[str, float], target: dict[str, float], dt: float) -> None:
    for name, ch in drive.spin.items():
        w = rates.get(name, 0.0)
        target[name] += w * dt
        data.ctrl[ch.actuator] = ch.gear * (target[name] if ch.mode == "position" else w)
    for name, ch in drive.steer.items():
        goal = ch.gear * steer.get(name, 0.0)
        if ch.mode == "rate":
            lo, hi = drive.model.actuator_ctrlrange[ch.actuator]
            rate = (goal - data.act[drive.model.actuator_actadr[ch.actuator]]) / 0.05
            data.ctrl[ch.actuator] = np.clip(rate, lo, hi) if hi > lo else rate
        else:
            data.ctrl[ch.actuator] = goal


def run(drive: Drive, found: Wheels, man: Manoeuvre, duration: float, ref: np.ndarray,
        model: mujoco.MjModel | None = None, phases: dict[int, float] | None = None
        ) -> Record:
    """Drive ``man`` for ``duration`` s (ramp included) on ``model`` (default the drive's).

    ``phases``: start angles of hinge joints by id (the wheels' phase: which roller is
    down), set before the settle.

    Raises:
        SimulationDivergedError: the state became NaN or infinite.
    """
    model = copy.deepcopy(model or drive.model)
    model.opt.enableflags |= int(mujoco.mjtEnableBit.mjENBL_ENERGY)
    data = mujoco.MjData(model)
    for j, angle in (phases or {}).items():
        data.qpos[model.jnt_qposadr[j]] = angle
    dt = model.opt.timestep
    twist = np.array(man.twist)
    # The judged point is the reference point: its twist is (v_c(ref), r).
    twist_ref = np.array([*contact_velocity(tuple(ref), twist), twist[2]])
    mujoco.mj_forward(model, data)
    sense = {w.name: float(np.sign(data.xaxis[w.steer_joint][2]) or 1.0) for w in found.wheels
             if w.kind == "steerable"}
    steer, rates = {}, {}
    for w in found.wheels:
        beta = 0.0
        if w.kind == "steerable":
            beta = steer_angle(w, twist, sense[w.name])
            steer[w.name] = beta
        if w.name in drive.spin:
            rates[w.name] = float(wheel_row(w, sense.get(w.name, 1.0) * beta) @ twist)
    wheel_speed = max((abs(rates[n]) * w.radius for w in found.wheels for n in [w.name]
                       if n in rates), default=0.0)
    target = {n: float(data.qpos[model.jnt_qposadr[ch.joint]]) for n, ch in drive.spin.items()}
    probe = _Probe(model, found, ref)
    every = max(1, round(SAMPLE / dt))
    start = time.perf_counter()
    for _ in range(round(SETTLE / dt)):
        _command(drive, data, {}, steer, target, dt)
        mujoco.mj_step(model, data)
    ideal = probe.pose(data)
    rows: dict[str, list] = {k: [] for k in ("time", "sim", "ideal", "height", "slip", "on")}
    prev = np.array([data.xanchor[w.joint] for w in found.wheels])
    nsteps = round(duration / dt)
    probe.depth = 0.0
    for k in range(1, nsteps + 1):
        t = k * dt
        scale = min(1.0, (t - 0.5 * dt) / RAMP)
        _command(drive, data, {n: scale * r for n, r in rates.items()}, steer, target, dt)
        mujoco.mj_step(model, data)
        u, v, r = scale * twist_ref
        mid = ideal[2] + 0.5 * r * dt
        ideal = ideal + dt * np.array([u * np.cos(mid) - v * np.sin(mid),
                                       u * np.sin(mid) + v * np.cos(mid), r])
        if k % every == 0:
            if not (np.isfinite(data.qpos).all() and np.isfinite(data.qvel).all()):
                raise SimulationDivergedError(f"{man.name}: the state diverged at t = {t:.3f} s")
            now = np.array([data.xanchor[w.joint] for w in found.wheels])
            rows["time"].append(t)
            rows["sim"].append(probe.pose(data))
            rows["ideal"].append(ideal.copy())
            rows["height"].append(now[:, 2] - probe.floor_z)
            rows["slip"].append(probe.slips(data, prev, every * dt))
            rows["on"].append(probe.contacts(data))
            prev = now
    mujoco.mj_forward(model, data)
    kinetic0 = float(data.energy[1])
    model.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_ACTUATION)
    energy = [float(data.energy.sum())]
    for _ in range(round(COAST / dt)):
        mujoco.mj_step(model, data)
        energy.append(float(data.energy.sum()))
    if not np.isfinite(energy).all():
        raise SimulationDivergedError(f"{man.name}: the state diverged while coasting")
    wall = time.perf_counter() - start
    return Record(np.array(rows["time"]), np.array(rows["sim"]), np.array(rows["ideal"]),
                  np.array(rows["height"]), np.array(rows["slip"]), np.array(rows["on"]),
                  probe.depth, np.array(energy), kinetic0, wall,
                  SETTLE + duration + COAST, wheel_speed)
