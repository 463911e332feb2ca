"""The wheels of a user's robot, as the audit needs them: kind, geometry, rolling radius.

The kinds and the Campion class come from :mod:`wmr_mujoco.models.classify`; this
module adds what driving and judging need, and two readings the classifier leaves open:

* a "wheel" whose colliders are not round about its joint (``ripple`` of the envelope,
  :mod:`~wmr_mujoco.models.support`, above :data:`ROUND_RIPPLE`) is a limb, not a wheel:
  a humanoid's hip is never called a wheel;
* a rigid collider sliding on the floor is a skid outside the theory, unless it is
  frictionless (``condim`` 1 or zero sliding friction): then it is an ideal ball caster;
* a robot whose fixed wheels lie on more than one axle only because of UNDRIVEN fixed
  wheels (a caster wheel on a plain hinge, no swivel) is classified from the driven ones
  and the undriven ones are reported as scrubbing wheels (a diagnosis).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import mujoco
import numpy as np

from wmr_mujoco.analytic.campion import Classification, Wheel, classify_wheels
from wmr_mujoco.audit.errors import AuditInputError, NotWheeledError
from wmr_mujoco.models import classify
from wmr_mujoco.models.colliders import colliders, is_collider
from wmr_mujoco.models.support import envelope
from wmr_mujoco.sim.stepping import SimulationDivergedError

#: Envelope ripple above which a jointed collider is not a wheel (a rolling ring of
#: rollers ripples a few per cent; a limb's collider seen from its joint, tens).
ROUND_RIPPLE = 0.25
_SKID = "slides on the floor: a skid, outside the theory"


@dataclass(frozen=True)
class AuditWheel:
    """One wheel with what the audit measures it by.

    Attributes:
        wheel: the classifier's :class:`~wmr_mujoco.analytic.campion.Wheel` (position,
            axle and radius in the chassis frame after settling).
        joint: id of its spin joint (the ball joint of a ball wheel).
        geoms: ids of its colliders (hub and rollers).
        radius: rolling radius from the colliders' envelope, m.
        ripple: the envelope's ripple, a fraction.
        steer_joint: id of the steering hinge (steerable and castor wheels), else -1.
        driven: whether an actuator moves its spin joint.
    """

    wheel: Wheel
    joint: int
    geoms: tuple[int, ...]
    radius: float
    ripple: float
    steer_joint: int = -1
    driven: bool = False

    @property
    def name(self) -> str:
        """The spin joint's name."""
        return self.wheel.name

    @property
    def kind(self) -> str:
        """fixed, steerable, castor, swedish or ball."""
        return self.wheel.kind


@dataclass(frozen=True)
class Wheels:
    """The audit's reading of the robot.

    Attributes:
        wheels: every wheel found.
        classification: the Campion class of the wheels that define the kinematics.
        chassis: id of the chassis body.
        scrubbing: undriven fixed wheels off the drive axle, left out of the class.
        notes: the classifier's notes plus the audit's.
    """

    wheels: tuple[AuditWheel, ...]
    classification: Classification
    chassis: int
    scrubbing: tuple[AuditWheel, ...] = ()
    notes: tuple[str, ...] = ()


def joint_id(model: mujoco.MjModel, name: str) -> int:
    """Id of a joint by the classifier's name (``#i`` for an unnamed joint)."""
    if name.startswith("#") and name[1:].isdigit():
        return int(name[1:])
    return mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)


def subtree_bodies(model: mujoco.MjModel, body: int) -> list[int]:
    """``body`` and every body below it."""
    out = [body]
    for b in range(body + 1, model.nbody):
        if model.body_parentid[b] in out:
            out.append(b)
    return out


def top_down(model: mujoco.MjModel, body: int) -> list[int]:
    """Bodies from the top-level ancestor (child of the world) down to ``body``."""
    path = [body]
    while model.body_parentid[path[-1]] != 0:
        path.append(int(model.body_parentid[path[-1]]))
    return path[::-1]


def driven_joints(model: mujoco.MjModel) -> set[int]:
    """Joints an actuator moves: directly, or through a fixed tendon."""
    out: set[int] = set()
    for a in range(model.nu):
        trn, target = int(model.actuator_trntype[a]), int(model.actuator_trnid[a, 0])
        if trn in (int(mujoco.mjtTrn.mjTRN_JOINT), int(mujoco.mjtTrn.mjTRN_JOINTINPARENT)):
            out.add(int(target))
        elif trn == int(mujoco.mjtTrn.mjTRN_TENDON):
            adr, num = model.tendon_adr[target], model.tendon_num[target]
            out |= {int(model.wrap_objid[w]) for w in range(adr, adr + num)
                    if model.wrap_type[w] == mujoco.mjtWrap.mjWRAP_JOINT}
    return out


def settle(model: mujoco.MjModel) -> mujoco.MjData:
    """The model after :data:`classify.SETTLE_TIME` s at zero controls."""
    data = mujoco.MjData(model)
    for _ in range(max(1, round(classify.SETTLE_TIME / model.opt.timestep))):
        mujoco.mj_step(model, data)
    return data


def unstable_at_rest(model: mujoco.MjModel) -> None:
    """Raise if the model blows up at rest (MuJoCo's bad-acceleration warning).

    The usual cause is a velocity gain too stiff for an explicit integrator: the servo
    ``kv`` (times gear²) over the joint's own inertia ``M_jj`` is stable under Euler only
    for ``kv Δt / M_jj < 2``; the message names every such actuator.

    Raises:
        SimulationDivergedError: the model diverged while settling.
    """
    data = settle(model)
    if data.warning[int(mujoco.mjtWarning.mjWARN_BADQACC)].number == 0:
        return
    causes = []
    if int(model.opt.integrator) in (int(mujoco.mjtIntegrator.mjINT_EULER),
                                     int(mujoco.mjtIntegrator.mjINT_RK4)):
        data = mujoco.MjData(model)
        mujoco.mj_forward(model, data)
        full = np.zeros((model.nv, model.nv))
        mujoco.mj_fullM(model, data, full)
        for a in range(model.nu):
            if int(model.actuator_trntype[a]) != int(mujoco.mjtTrn.mjTRN_JOINT):
                continue
            dof = model.jnt_dofadr[model.actuator_trnid[a, 0]]
            kv = -model.actuator_biasprm[a, 2] * model.actuator_gear[a, 0] ** 2
            ratio = kv * model.opt.timestep / full[dof, dof]
            if ratio > 2.0:
                name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, a) or f"#{a}"
                causes.append(f"actuator {name!r}: kv·Δt/M_jj = {ratio:.0f} > 2")
    why = (f"; under the explicit integrator {', '.join(causes)} (use integrator="
           f"\"implicitfast\" or a smaller kv)" if causes else "")
    raise SimulationDivergedError(f"the model is unstable at rest: MuJoCo reset it while it "
                                  f"settled at zero controls{why}")


def _frictionless_skids(model: mujoco.MjModel, data: mujoco.MjData) -> bool:
    """Whether every rigid chassis collider touching the floor is frictionless."""
    floor = {g for g in colliders(model) if model.geom_bodyid[g] == 0}
    skids = set()
    for c in data.contact[:data.ncon]:
        g1, g2 = int(c.geom[0]), int(c.geom[1])
        other = g2 if g1 in floor else g1 if g2 in floor else None
        if other is not None:
            path = top_down(model, int(model.geom_bodyid[other]))
            if not any(model.body_jntnum[b] for b in path[1:]):
                skids.add(other)  # a collider rigid with the chassis
    floor_priority = max((int(model.geom_priority[g]) for g in floor), default=0)
    floor_condim = max((int(model.geom_condim[g]) for g in floor), default=3)

    def frictionless(g: int) -> bool:  # MuJoCo: the higher priority, else the larger condim
        condim = model.geom_condim[g] if model.geom_priority[g] > floor_priority else max(
            model.geom_condim[g], floor_condim)
        return condim == 1 or model.geom_friction[g, 0] == 0

    return bool(skids) and all(frictionless(g) for g in skids)


def _audit_wheel(model: mujoco.MjModel, data: mujoco.MjData, w: Wheel,
                 driven: set[int]) -> AuditWheel:
    j = joint_id(model, w.name)
    bodies = subtree_bodies(model, int(model.jnt_bodyid[j]))
    geoms = tuple(g for b in bodies for g in range(model.body_geomadr[b], model.body_geomadr[b]
                                                   + model.body_geomnum[b])
                  if is_collider(model, g))
    axis = data.xaxis[j] if w.kind != "ball" else np.array([0.0, 1.0, 0.0])
    env = envelope(model, data, geoms, data.xanchor[j], axis)
    radius, ripple = (env.radius, env.ripple) if env else (w.radius, float("nan"))
    steer = joint_id(model, w.steer_joint) if w.steer_joint else -1
    return AuditWheel(replace(w, radius=radius), j, geoms, radius, ripple, steer, j in driven)


def find(model: mujoco.MjModel) -> Wheels:
    """The wheels and class of a compiled model with a floor.

    Raises:
        NotWheeledError: nothing wheel-like (a humanoid), a limb taken for a wheel,
            wheels outside the theory (each named with the reason).
        AuditInputError: several robots on the floor, or the model diverges at rest.
    """
    unstable_at_rest(model)
    try:
        found, notes = classify.find_wheels(model)
    except ValueError as err:
        msg = str(err)
        if "several top-level" in msg or "diverged" in msg or "horizontal" in msg:
            raise AuditInputError(msg) from None
        raise NotWheeledError(f"not a wheeled robot: {msg}") from None
    data = settle(model)
    driven = driven_joints(model)
    wheels = [_audit_wheel(model, data, w, driven) for w in found]
    limbs = [w for w in wheels if w.kind != "ball" and not w.ripple <= ROUND_RIPPLE]
    if limbs:
        named = "; ".join(f"joint {w.name!r} ({w.kind} by its joint chain) has colliders "
                          f"that are not round about it (envelope ripple "
                          f"{100 * w.ripple:.0f} %, a wheel's is under "
                          f"{100 * ROUND_RIPPLE:.0f} %)" for w in limbs)
        raise NotWheeledError(f"not a wheeled robot: {named}")
    notes = list(notes)
    if any(n.endswith(_SKID) for n in notes) and _frictionless_skids(model, data):
        notes = [n.replace(_SKID, "slides on the floor without friction: an ideal ball "
                                  "caster") for n in notes]
    chassis = top_down(model, int(model.jnt_bodyid[wheels[0].joint]))[0]
    c = classify_wheels(tuple(w.wheel for w in wheels), tuple(notes))
    scrubbing: tuple[AuditWheel, ...] = ()
    if c.reason.startswith("fixed wheels on more than one axle"):
        scrubbing = tuple(w for w in wheels if w.kind == "fixed" and not w.driven)
        keep = tuple(w.wheel for w in wheels if w not in scrubbing)
        if scrubbing and keep:
            c = classify_wheels(keep, tuple(notes))
    if c.reason:
        names = ", ".join(f"{w.name!r} ({w.kind})" for w in wheels)
        raise NotWheeledError(f"wheels {names} found, but the audit cannot classify the robot: "
                              f"{c.reason}")
    return Wheels(tuple(wheels), c, chassis, scrubbing, c.notes)
