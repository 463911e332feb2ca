"""omni3's analytic models' parameters, read from the compiled model (the one reader).

Everything :class:`~wmr_mujoco.analytic.omni_hybrid.OmniHybrid` needs comes from the
compiled ``MjModel`` (masses, inertias, armatures, roller placement and collider sizes)
and the drive law from its actuators (gain and ``forcerange``): nothing is fitted. The
reduced Lagrange model (:func:`dynamics_from_model`) is the hybrid model without its rows,
rollers, slip and impacts (:func:`lagrange`), from the same reading.
"""

from __future__ import annotations

import mujoco
import numpy as np

from wmr_mujoco.analytic import omni_kinematics as ok
from wmr_mujoco.analytic.omni_dynamics import OmniDynamics
from wmr_mujoco.analytic.omni_hybrid import Drive, OmniHybrid, RollerGeometry
from wmr_mujoco.models.actuation import ActuationMode

WHEELS = ("wheel1", "wheel2", "wheel3")


def _inertia_about(model: mujoco.MjModel, data: mujoco.MjData, bodies: list[int],
                   point: np.ndarray, frame: np.ndarray) -> np.ndarray:
    """Composite 3×3 inertia of ``bodies`` about ``point``, in ``frame`` (world ← frame)."""
    total = np.zeros((3, 3))
    for b in bodies:
        rot = data.ximat[b].reshape(3, 3)
        inertia = rot @ np.diag(model.body_inertia[b]) @ rot.T
        r = data.xipos[b] - point
        total += inertia + model.body_mass[b] * ((r @ r) * np.eye(3) - np.outer(r, r))
    return frame.T @ total @ frame


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


def hybrid_from_model(model: mujoco.MjModel, compliant: bool = True) -> OmniHybrid:
    """:class:`OmniHybrid` of a compiled omni3 model (at its reference pose).

    With ``compliant`` the hand-over loss of the soft contact uses the static
    penetration :func:`static_penetration`; without, contacts are rigid.

    Raises:
        ValueError: the model has no wheel joints or rollers that are ellipsoids.
    """
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    base = model.body("platform").id
    centre = data.xpos[base].copy()
    frame = data.xmat[base].reshape(3, 3)
    robot = [b for b in range(1, model.nbody)]
    wheel = model.joint(WHEELS[0])
    wb = int(wheel.bodyid[0])
    children = [b for b in range(model.nbody) if model.body_parentid[b] == wb]
    subtree = [wb, *children]
    axis = data.xaxis[wheel.id]
    i_axial = float(axis @ _inertia_about(model, data, subtree, data.xanchor[wheel.id],
                                          np.eye(3)) @ axis)
    angles, offsets, size, friction, timeconst = [], [], None, 1.0, 0.0
    for c in children:
        x, y, z = model.body_pos[c]
        angles.append(np.arctan2(x, z))
        offsets.append(y)
        ellipsoid = mujoco.mjtGeom.mjGEOM_ELLIPSOID
        geoms = [g for g in range(model.ngeom) if model.geom_bodyid[g] == c
                 and model.geom_conaffinity[g] and model.geom_type[g] == ellipsoid]
        if len(geoms) != 1:
            raise ValueError(f"roller body {model.body(c).name!r} has {len(geoms)} ellipsoid "
                             f"colliders; the hybrid model needs exactly one")
        size = model.geom_size[geoms[0]]
        friction = float(model.geom_friction[geoms[0], 0])  # rollers have priority 1
        timeconst = float(model.geom_solref[geoms[0], 0])
    if size is None:
        raise ValueError("the wheel has no roller bodies")
    d = float(np.mean(np.hypot(model.body_pos[children, 0], model.body_pos[children, 2])))
    roller_joint = int(model.body_jntadr[children[0]])
    roller_axial = float(model.body_inertia[children[0]][2]
                         + model.dof_armature[model.jnt_dofadr[roller_joint]])
    rollers = RollerGeometry(d, float(size[0]), float(size[2]), np.asarray(angles),
                             np.asarray(offsets))
    wheel_pos = np.array([model.body_pos[model.joint(w).bodyid[0]] for w in WHEELS])
    return OmniHybrid(
        mass=float(sum(model.body_mass[robot])),
        inertia=_inertia_about(model, data, robot, centre, frame),
        wheel_axial=i_axial,
        wheel_armature=float(model.dof_armature[wheel.dofadr[0]]),
        roller_axial=roller_axial,
        radius=float(rollers.rolling_radius(0.0)),
        distance=float(np.mean(np.linalg.norm(wheel_pos[:, :2], axis=1))),
        rollers=rollers,
        wheel_angles=np.arctan2(wheel_pos[:, 1], wheel_pos[:, 0]),
        gravity=float(-model.opt.gravity[2]),
        penetration=static_penetration(model) if compliant else 0.0,
        friction=friction,
        contact_timeconst=timeconst if compliant else 0.0)


def lagrange(hy: OmniHybrid) -> OmniDynamics:
    """The reduced Lagrange model of the same robot.

    ``M``, ``I_z``, ``I_w`` (with the armature), mean lever L; no rows, roller spin, slip
    or impacts.
    """
    return OmniDynamics(mass=hy.mass, yaw_inertia=float(hy.inertia[2, 2]),
                        wheel_inertia=hy.wheel_inertia,
                        layout=ok.symmetric_layout(hy.radius, hy.distance))


def dynamics_from_model(model: mujoco.MjModel) -> OmniDynamics:
    """Lagrange-model parameters read from the compiled omni model.

    ``M``: total mass; ``I_z``: composite yaw inertia about the centre; ``I_w``: each
    wheel's inertia about its axle (hub, rollers with parallel-axis terms, and the
    hinge's armature). The rollers' spin about their own axes is neglected.
    """
    return lagrange(hybrid_from_model(model, compliant=False))


def drive_from_model(model: mujoco.MjModel, mode: ActuationMode | str) -> Drive:
    """Drive law of wheel 1's actuator: gain ``k_v`` (rate mode) and ``forcerange``."""
    act = model.actuator(WHEELS[0])
    limit = float(act.forcerange[1])
    if ActuationMode(mode) is ActuationMode.RATE:
        return Drive("rate", limit, gain=float(act.gainprm[0]))
    return Drive("torque", limit)


def roller_rates(model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
    """(3, n) spins of every roller of every wheel, in :class:`RollerGeometry` order."""
    out = []
    for w in WHEELS:
        wb = model.joint(w).bodyid[0]
        kids = [b for b in range(model.nbody) if model.body_parentid[b] == wb]
        out.append([data.qvel[model.jnt_dofadr[model.body_jntadr[b]]] for b in kids])
    return np.asarray(out)
