"""Measurements on omni-wheeled models, for any robot whose wheels carry free rollers.

The wheel layout is read from a compiled model (:func:`layout_from_model`), so the same
probes measure this package's models and a foreign (peer) model alike. The probes
(:class:`RollerRateProbe`, :class:`WheelRateProbe`, :class:`YawRippleProbe`) take an
:class:`OmniAdapter`: an :class:`~wmr_mujoco.validation.adapters.Adapter` that also
gives its wheel layout and the body twist its input commands.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import mujoco
import numpy as np

from wmr_mujoco.analytic import omni_kinematics as ok
from wmr_mujoco.analytic.omni_dynamics import OmniDynamics
from wmr_mujoco.analytic.omni_hybrid import Drive, OmniHybrid, RollerGeometry
from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.colliders import colliders
from wmr_mujoco.sim.inertia import hinge_inertia, inertia_about_axis, inertia_tensor_about
from wmr_mujoco.sim.soft_contact import slip_relaxation
from wmr_mujoco.validation.adapters import POSE_UNITS, Adapter, base_pose, body_twist
from wmr_mujoco.validation.metrics import Metric, Sample, Target, rms
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.signals import Signal, const

#: Probes start after this many seconds (ramps done, transients settled).
STEADY_AFTER = 1.0
#: Open-loop manoeuvres of omni-wheeled robots: translation directions (degrees in the
#: body frame), speed (m/s), yaw rate (rad/s) and the ramp from rest (s).
DIRECTIONS_DEG = tuple(range(0, 360, 45))
SPEED = 0.3
YAW_RATE = 1.0
RAMP = 0.5
#: Key of the roller-rate target in a robot's target table.
ROLLER_RATE_PCT = "roller rate error % (median)"


@runtime_checkable
class OmniAdapter(Adapter, Protocol):
    """An adapter of an omni-wheeled robot."""

    @property
    def layout(self) -> ok.WheelLayout:
        """The analytic model's wheel layout."""
        ...

    def twist(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Body twist ``ν = (u, v, r)`` commanded by input ``u``."""
        ...


@dataclass(frozen=True)
class OmniModelInfo:
    """What the probes need to know about a compiled omni-wheeled model.

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

    Raises:
        ValueError: a wheel joint without exactly one actuator.
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


def dynamics_from_model(model: mujoco.MjModel, layout: ok.WheelLayout, centre_body: str,
                        wheel_joint: str) -> OmniDynamics:
    """Parameters of the reduced Lagrange model read from a compiled omni-wheeled model.

    ``M``: total mass of the robot; ``I_z``: its composite yaw inertia about the vertical
    through ``centre_body``'s origin; ``I_w``: ``wheel_joint``'s wheel (hub and rollers,
    with parallel-axis terms) about its axle plus the hinge's armature
    (:func:`wmr_mujoco.sim.inertia.hinge_inertia`). The rollers' spin about their own
    axes is neglected. ``layout`` is the analytic wheel layout the model is judged with.
    """
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    centre = data.xpos[model.body(centre_body).id]
    robot = list(range(1, model.nbody))
    return OmniDynamics(
        mass=float(sum(model.body_mass[robot])),
        yaw_inertia=inertia_about_axis(model, data, robot, centre, np.array([0.0, 0.0, 1.0])),
        wheel_inertia=hinge_inertia(model, wheel_joint), layout=layout)


def static_penetration(model: mujoco.MjModel, settle: float = 1.0) -> float:
    """Mean penetration ``δ = −dist`` of the roller contacts of the robot at rest, m.

    A static property of the soft contact (solref/solimp under the robot's weight),
    measured once at rest: no motion, nothing taken from the runs it is used to predict.
    """
    data = mujoco.MjData(model)
    for _ in range(round(settle / model.opt.timestep)):
        mujoco.mj_step(model, data)
    mujoco.mj_forward(model, data)
    floor = model.geom("floor").id
    dist = [c.dist for c in data.contact[:data.ncon] if floor in (c.geom1, c.geom2)]
    if not dist:
        raise ValueError("the robot does not touch the floor after settling")
    return float(max(0.0, -np.mean(dist)))


def hybrid_from_model(model: mujoco.MjModel, layout: ok.WheelLayout, centre_body: str,
                      wheel_joints: Sequence[str], compliant: bool = True) -> OmniHybrid:
    """The hybrid model of a compiled three-omni-wheel model with ellipsoid rollers.

    :class:`~wmr_mujoco.analytic.omni_hybrid.OmniHybrid` at the reference pose.

    ``M``, ``I_w`` (hinge inertia with armature) from :func:`dynamics_from_model`, so the
    Lagrange and the hybrid model come from one reading; the composite 3×3 inertia about
    ``centre_body`` (:func:`~wmr_mujoco.sim.inertia.inertia_tensor_about`), in its frame;
    the first wheel's rollers (child bodies of the wheel: angle around the axle, axial
    offset, one ellipsoid collider each with its size, friction and solref time
    constant; the roller hinge's inertia and armature); the wheel centres' radius and
    angles. With ``compliant`` the hand-over loss of the soft contact uses
    :func:`static_penetration`, and a hand-over's jump is spread as the contact's
    friction rows remove a slip at the model's step
    (:func:`~wmr_mujoco.sim.soft_contact.slip_relaxation` of the roller's ``solref`` and
    ``solimp`` at that penetration, with ``impratio`` for elliptic cones; 0 for solref
    given as direct stiffness and damping); without, contacts are rigid.

    Raises:
        ValueError: a wheel without roller bodies, or a roller without exactly one
            ellipsoid collider.
    """
    lagrange = dynamics_from_model(model, layout, centre_body, wheel_joints[0])
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    base = model.body(centre_body).id
    frame = data.xmat[base].reshape(3, 3)
    robot = list(range(1, model.nbody))
    inertia = frame.T @ inertia_tensor_about(model, data, robot, data.xpos[base]) @ frame
    wheel = model.joint(wheel_joints[0])
    wb = int(wheel.bodyid[0])
    children = [b for b in range(model.nbody) if model.body_parentid[b] == wb]
    if not children:
        raise ValueError(f"wheel {wheel_joints[0]!r} has no roller bodies")
    angles, offsets, size, friction, timeconst, solimp = [], [], None, 1.0, 0.0, None
    for c in children:
        x, y, z = model.body_pos[c]
        angles.append(np.arctan2(x, z))
        offsets.append(y)
        geoms = [g for g in range(model.ngeom) if model.geom_bodyid[g] == c
                 and model.geom_conaffinity[g]
                 and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_ELLIPSOID]
        if len(geoms) != 1:
            raise ValueError(f"roller body {model.body(c).name!r} has {len(geoms)} ellipsoid "
                             f"colliders; the hybrid model needs exactly one")
        size = model.geom_size[geoms[0]]
        friction = float(model.geom_friction[geoms[0], 0])  # rollers have priority 1
        timeconst = float(model.geom_solref[geoms[0], 0])
        solimp = model.geom_solimp[geoms[0]]
    d = float(np.mean(np.hypot(model.body_pos[children, 0], model.body_pos[children, 2])))
    roller_joint = int(model.body_jntadr[children[0]])
    roller_axial = float(model.body_inertia[children[0]][2]
                         + model.dof_armature[model.jnt_dofadr[roller_joint]])
    rollers = RollerGeometry(d, float(size[0]), float(size[2]), np.asarray(angles),
                             np.asarray(offsets))
    wheel_pos = np.array([model.body_pos[model.joint(w).bodyid[0]] for w in wheel_joints])
    armature = float(model.dof_armature[wheel.dofadr[0]])
    penetration = static_penetration(model) if compliant else 0.0
    elliptic = model.opt.cone == mujoco.mjtCone.mjCONE_ELLIPTIC
    refsafe = not model.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_REFSAFE
    relaxation = (slip_relaxation(model.opt.timestep, timeconst, solimp, penetration,
                                  float(model.opt.impratio) if elliptic else 1.0, refsafe)
                  if compliant and timeconst > 0 else 0.0)
    return OmniHybrid(
        mass=lagrange.mass, inertia=inertia,
        wheel_axial=lagrange.wheel_inertia - armature, wheel_armature=armature,
        roller_axial=roller_axial, radius=float(rollers.rolling_radius(0.0)),
        distance=float(np.mean(np.linalg.norm(wheel_pos[:, :2], axis=1))),
        rollers=rollers, wheel_angles=np.arctan2(wheel_pos[:, 1], wheel_pos[:, 0]),
        gravity=float(-model.opt.gravity[2]),
        penetration=penetration, friction=friction,
        contact_timeconst=timeconst if compliant else 0.0, handover_relaxation=relaxation)


def lagrange_of(hy: OmniHybrid) -> OmniDynamics:
    """The reduced Lagrange model inside a hybrid one: the same reading.

    Mean lever L; no rows, roller spin, slip or impacts (:func:`dynamics_from_model`).
    """
    return OmniDynamics(mass=hy.mass, yaw_inertia=float(hy.inertia[2, 2]),
                        wheel_inertia=hy.wheel_inertia,
                        layout=ok.symmetric_layout(hy.radius, hy.distance))


def drive_from_model(model: mujoco.MjModel, wheel_joint: str,
                     mode: ActuationMode | str) -> Drive:
    """Drive law of a wheel's actuator: gain ``k_v`` (rate mode) and ``forcerange``."""
    act = model.actuator(wheel_joint)
    limit = float(act.forcerange[1])
    if ActuationMode(mode) is ActuationMode.RATE:
        return Drive("rate", limit, gain=float(act.gainprm[0]))
    return Drive("torque", limit)


def roller_rates(model: mujoco.MjModel, qvel: np.ndarray,
                 wheel_joints: Sequence[str]) -> np.ndarray:
    """(wheels, rollers) spins of every roller (child body) of every wheel, from ``qvel``."""
    out = []
    for w in wheel_joints:
        wb = model.joint(w).bodyid[0]
        kids = [b for b in range(model.nbody) if model.body_parentid[b] == wb]
        out.append([qvel[model.jnt_dofadr[model.body_jntadr[b]]] for b in kids])
    return np.asarray(out)


@dataclass(frozen=True)
class OmniDynamicsAdapter:
    """An omni-wheeled robot under wheel torques: ``x = (X, Y, ψ, u, v, r)``.

    The reduced Lagrange equations
    (:meth:`~wmr_mujoco.analytic.omni_dynamics.OmniDynamics.state_derivative`) against
    the ``base`` site's pose and body twist.

    Attributes:
        dynamics: the reduced model (e.g. from :func:`dynamics_from_model`).
        wheel_joints: the wheel hinges, in the torques' order.
        friction: the floor's Coulomb coefficient μ (for traction checks).
    """

    dynamics: OmniDynamics
    wheel_joints: tuple[str, ...]
    friction: float = 1.0
    mode: ActuationMode = ActuationMode.TORQUE
    state_names: tuple[str, ...] = ("x", "y", "heading", "u", "v", "r")
    state_units: tuple[str, ...] = (*POSE_UNITS, "m/s", "m/s", "rad/s")
    lateral_wheels: tuple[str, ...] = ()

    def controls(self, u: np.ndarray, analytic_state: np.ndarray) -> np.ndarray:
        """Torques as given."""
        return np.asarray(u, float)

    def rhs(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Reduced Lagrange equations with the world pose."""
        return self.dynamics.state_derivative(x, u)

    def sim_state(self, model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        """Pose and body twist of the ``base`` site."""
        return np.concatenate([base_pose(model, data), body_twist(model, data)])


def roller_rate_errors(model: mujoco.MjModel, data: mujoco.MjData, info: OmniModelInfo,
                       slide_speeds: np.ndarray) -> list[float]:
    """Relative errors ``|ω_r ρ − s| / s`` of the rollers touching the floor now.

    ``s`` is the slide speed along the roller axis at each wheel's contact implied by the
    commanded twist, ``ρ`` the contact's distance from the roller axis and ``ω_r`` the
    roller's measured spin rate. Contacts of wheels sliding slower than 1 mm/s are skipped.
    """
    if data.ncon == 0:
        return []
    wheel_of = np.full(model.nbody, -1)
    for i, j in enumerate(info.wheel_joints):
        wheel_of[model.jnt_bodyid[j]] = i
    g1, g2 = data.contact.geom1[:data.ncon], data.contact.geom2[:data.ncon]
    geom = np.where(model.geom_bodyid[g1] == 0, g2, g1)
    body = model.geom_bodyid[geom]
    wheel = wheel_of[model.body_parentid[body]]
    roller = (wheel >= 0) & (model.body_jntnum[body] == 1)
    jnt = model.body_jntadr[body[roller]]
    axis = data.xaxis[jnt]
    rel = data.contact.pos[:data.ncon][roller] - data.xanchor[jnt]
    rho = np.linalg.norm(rel - axis * np.sum(rel * axis, axis=1)[:, None], axis=1)
    slide = np.abs(np.asarray(slide_speeds, float)[wheel[roller]])
    omega = np.abs(data.qvel[model.jnt_dofadr[jnt]])
    keep = (slide >= 1e-3) & (rho >= 1e-6)
    return (np.abs(omega * rho - slide)[keep] / slide[keep]).tolist()


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
    geoms = [g for g in colliders(model) if (model.geom(g).name or "").startswith(roller_prefix)]
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


@dataclass
class RollerRateProbe:
    """Contacting rollers' spin rates against slide speed / ρ, after :data:`STEADY_AFTER`."""

    info: OmniModelInfo
    adapter: OmniAdapter
    target: Target | None
    errors: list[float] = field(default_factory=list)

    def observe(self, sample: Sample) -> None:
        """Errors of the rollers in contact at this step."""
        if sample.t > STEADY_AFTER:
            slide = ok.roller_slide_speeds(self.adapter.layout,
                                           self.adapter.twist(sample.u, sample.x))
            self.errors += roller_rate_errors(sample.model, sample.data, self.info, slide)

    def metrics(self) -> list[Metric]:
        """Median (judged) and 95th percentile, in %."""
        if not self.errors:
            return []
        return [Metric("roller rate error (median)", 100.0 * float(np.median(self.errors)),
                       "%", self.target),
                Metric("roller rate error (95th percentile)",
                       100.0 * float(np.percentile(self.errors, 95)), "%")]


@dataclass
class WheelRateProbe:
    """Measured wheel rates against the commanded ``θ̇ = H ν`` (rate servos only)."""

    wheel_dofs: tuple[int, ...]
    errors: list[float] = field(default_factory=list)

    def observe(self, sample: Sample) -> None:
        """``|θ̇ − θ̇_cmd| / |θ̇_cmd|`` at this step, once the commanded rates exceed 0.5."""
        if sample.t > STEADY_AFTER and np.linalg.norm(sample.ctrl) > 0.5:
            rates = sample.data.qvel[list(self.wheel_dofs)]
            self.errors.append(float(np.linalg.norm(rates - sample.ctrl)
                                     / np.linalg.norm(sample.ctrl)))

    def metrics(self) -> list[Metric]:
        """RMS relative error, reported."""
        return [Metric("wheel rate error vs H ν (RMS)", 100.0 * rms(self.errors), "%")
                ] if self.errors else []


@dataclass
class YawRippleProbe:
    """Standard deviation of the base's yaw rate over the steady phase, / |commanded|."""

    base_body: int
    adapter: OmniAdapter
    rates: list[float] = field(default_factory=list)
    commanded: list[float] = field(default_factory=list)

    def observe(self, sample: Sample) -> None:
        """The base's world yaw rate and the commanded one at this step."""
        if sample.t > STEADY_AFTER:
            self.rates.append(float(sample.data.cvel[self.base_body][2]))
            self.commanded.append(float(self.adapter.twist(sample.u, sample.x)[2]))

    def metrics(self) -> list[Metric]:
        """``std(r) / |r_cmd|`` in %, where a constant yaw rate is commanded."""
        cmd = np.asarray(self.commanded)
        if not cmd.size or np.ptp(cmd) > 1e-9 or abs(cmd[0]) < 1e-9:
            return []
        return [Metric("yaw-rate ripple", 100.0 * float(np.std(self.rates)) / abs(cmd[0]),
                       "% of commanded")]


def omni_probes(scenario: Scenario, model: mujoco.MjModel, adapter: Adapter,
                targets: Mapping[str, Target]) -> _OmniProbes | None:
    """The roller, wheel-rate and yaw-ripple probes of a kinematic omni-wheel run."""
    if scenario.kind is not ScenarioKind.KINEMATIC or not isinstance(adapter, OmniAdapter):
        return None
    info = layout_from_model(model, adapter.wheel_joints)
    probes: list[RollerRateProbe | WheelRateProbe | YawRippleProbe] = [
        RollerRateProbe(info, adapter, targets.get(ROLLER_RATE_PCT)),
        YawRippleProbe(info.base_body, adapter)]
    if adapter.mode is ActuationMode.RATE:
        probes.insert(0, WheelRateProbe(tuple(int(model.jnt_dofadr[j])
                                              for j in info.wheel_joints)))
    return _OmniProbes(probes)


@dataclass
class _OmniProbes:
    """Several probes as one."""

    probes: list[RollerRateProbe | WheelRateProbe | YawRippleProbe]

    def observe(self, sample: Sample) -> None:
        """Pass the sample to each probe."""
        for p in self.probes:
            p.observe(sample)

    def metrics(self) -> list[Metric]:
        """Every probe's metrics, in order."""
        return [m for p in self.probes for m in p.metrics()]


def twist_inputs(twist: tuple[float, float, float], ramp: float = RAMP) -> tuple[Signal, ...]:
    """Body twist ``(u, v, r)`` inputs, each reached from rest by a linear ramp."""
    return tuple(const(c, ramp) if c else const(0.0) for c in twist)


def translation(deg: float, speed: float = SPEED) -> tuple[float, float, float]:
    """Body twist ``(s cos α, s sin α, 0)`` of a translation at ``α`` degrees."""
    a = np.radians(deg)
    return (speed * float(np.cos(a)), speed * float(np.sin(a)), 0.0)
