"""What a compiled roller-wheeled model says about itself.

Wheel layout, rollers, mass properties, and the analytic models built from them.

The wheel layout is read from a compiled model (:func:`layout_from_model`), so the same
probes measure this package's models and a foreign (peer) model alike.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.omni_dynamics import OmniDynamics
from wmr_mujoco.robots.roller_wheels.omni_hybrid import Drive, OmniHybrid, RollerGeometry
from wmr_mujoco.sim.floor_contact import FLOOR, touches_floor
from wmr_mujoco.sim.inertia import hinge_inertia, inertia_about_axis, inertia_tensor_about
from wmr_mujoco.sim.soft_contact import slip_relaxation


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


#: Models whose layout was read, as their saved bytes, with the joints and the result: a
#: family's members share one model, whose settle is then simulated once.
_READ: list[tuple[np.ndarray, tuple[str, ...], OmniModelInfo]] = []
#: Most models remembered (each its saved size, a few MB).
_READ_MAX = 4
_SCRATCH = [np.empty(0, np.uint8)]


def layout_from_model(model: mujoco.MjModel, wheel_joints: Sequence[str]) -> OmniModelInfo:
    """Read the wheel layout of a settled model from its geometry.

    For each wheel hinge with world axis ``a`` and centre ``c`` (relative to the base),
    the drive direction is ``a × ẑ`` (a positive rate rolls the centre that way) and the
    radius is the centre's height above the floor at rest.

    A model equal to one read before (every byte of its saved form: ``mj_saveModel``,
    a millisecond against the settle's many steps) gives that read's result again (the
    same floats: the settle is deterministic; the layout's arrays are read-only).

    Raises:
        ValueError: a wheel joint without exactly one actuator.
    """
    size = mujoco.mj_sizeModel(model)
    if _SCRATCH[0].size != size:  # one buffer reused: its pages are not faulted in anew
        _SCRATCH[0] = np.empty(size, np.uint8)
    saved = _SCRATCH[0]
    mujoco.mj_saveModel(model, None, saved)
    joints = tuple(wheel_joints)
    for bytes_, names, info in _READ:
        if names == joints and np.array_equal(bytes_, saved):
            return info
    info = _read_layout(model, joints)
    if len(_READ) >= _READ_MAX:
        _READ.pop(0)
    _READ.append((saved.copy(), joints, info))
    return info


def _read_layout(model: mujoco.MjModel, wheel_joints: Sequence[str]) -> OmniModelInfo:
    """:func:`layout_from_model` read from the settled model."""
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


def floor_contact(model: mujoco.MjModel, geom: int
                  ) -> tuple[float, float, np.ndarray, np.ndarray | None]:
    """``(μ, t_c, solimp, solreffriction)`` of a collider's contact with the ``floor``.

    From the ``<pair>`` of the geom and the floor where the scene has one (MuJoCo takes
    a pair's parameters whole), else from the geom (rollers have priority 1 over the
    floor, so theirs win); ``solreffriction`` None where no pair sets it.
    """
    floor = model.geom("floor").id
    for k in range(model.npair):
        if {int(model.pair_geom1[k]), int(model.pair_geom2[k])} == {floor, geom}:
            ref = model.pair_solreffriction[k].copy()
            return (float(model.pair_friction[k, 0]), float(model.pair_solref[k, 0]),
                    model.pair_solimp[k].copy(), ref if ref.any() else None)
    return (float(model.geom_friction[geom, 0]), float(model.geom_solref[geom, 0]),
            model.geom_solimp[geom].copy(), None)


def hybrid_from_model(model: mujoco.MjModel, layout: ok.WheelLayout, centre_body: str,
                      wheel_joints: Sequence[str], compliant: bool = True) -> OmniHybrid:
    """The hybrid model of a compiled three-omni-wheel model with ellipsoid rollers.

    :class:`~wmr_mujoco.robots.roller_wheels.omni_hybrid.OmniHybrid` at the reference pose.

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
    floor = int(model.geom(FLOOR).id)
    if not children:
        raise ValueError(f"wheel {wheel_joints[0]!r} has no roller bodies")
    angles, offsets, size = [], [], None
    friction, timeconst, solimp, friction_ref = 1.0, 0.0, None, None
    for c in children:
        x, y, z = model.body_pos[c]
        angles.append(np.arctan2(x, z))
        offsets.append(y)
        geoms = [g for g in range(model.ngeom) if model.geom_bodyid[g] == c
                 and touches_floor(model, g, floor)
                 and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_ELLIPSOID]
        if len(geoms) != 1:
            raise ValueError(f"roller body {model.body(c).name!r} has {len(geoms)} ellipsoid "
                             f"colliders; the hybrid model needs exactly one")
        size = model.geom_size[geoms[0]]
        friction, timeconst, solimp, friction_ref = floor_contact(model, geoms[0])
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
                                  float(model.opt.impratio) if elliptic else 1.0, refsafe,
                                  friction_ref)
                  if compliant and timeconst > 0 else 0.0)
    if compliant and friction_ref is not None:
        # The friction rows' own damping: a slip decays at d_f b = (1 − ρ)/Δt, which the
        # overlap friction reads as 2/t_c (OmniHybrid.contact_timeconst).
        timeconst = 2.0 * model.opt.timestep / (1.0 - relaxation)
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
