"""How the audit commands a robot: its own wheel servos when it has them, else its own.

A wheel's spin joint is commanded through an actuator on that joint (``gear`` g, so the
actuator's length is ``g q``) in one of three modes:

* ``velocity``: a velocity servo, ``ctrl = g ω`` (MuJoCo ``velocity``);
* ``rate``: an integrating servo, ``ctrl = g ω`` as well (``intvelocity``; its activation
  is the target angle);
* ``position``: a position servo, ``ctrl = g q_target`` with ``q_target`` the integral
  of ``ω``.

A steering joint takes a position servo (``ctrl = g β``) or an integrating one, whose
rate the audit sets to ``(g β − act)/τ`` until it holds the angle. The robot's own
actuators are used when every rolling wheel an actuator moves has one of those and every
steering joint has a servo (manoeuvres the driven wheels do not determine are left out:
:func:`~wmr_mujoco.audit.kinematics.infeasible`). Otherwise the audit removes the actuators on the
wheel and steering joints (and tendons through them) and imposes velocity servos on every
rolling wheel (``kv = I/τ`` with ``I = m R²/n + M_jj`` the inertia a wheel moves) and
position servos on the steering joints; the report says so. Under an explicit integrator
(Euler, RK4) a velocity gain above ``M_jj/Δt`` is unstable for a light wheel, so the
imposed wheel servos are position servos on the integrated wheel angle instead, with
``kp = min(I/τ², M_jj/(2Δt²))`` and ``kv = min(2I/τ, M_jj/(2Δt))``.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from wmr_mujoco.audit.kinematics import ROLLING_KINDS
from wmr_mujoco.audit.scene import Scene
from wmr_mujoco.audit.wheels import AuditWheel, Wheels

#: Time constant of the imposed wheel servos, s.
SERVO_TAU = 0.05
#: Time constant of the imposed steering servos, s.
STEER_TAU = 0.05
_IMPLICIT = (int(mujoco.mjtIntegrator.mjINT_IMPLICIT), int(mujoco.mjtIntegrator.mjINT_IMPLICITFAST))


@dataclass(frozen=True)
class Channel:
    """One commanded joint: actuator id, mode (velocity, rate, position), gear."""

    joint: int
    actuator: int
    mode: str
    gear: float


@dataclass(frozen=True)
class Drive:
    """The compiled model the audit drives and how.

    Attributes:
        model: compiled, with the imposed servos if any.
        spin: wheel name -> its spin channel (driven wheels only).
        steer: wheel name -> its steering channel (steerable wheels).
        imposed: whether the audit imposed its own servos.
        statement: one sentence for the report.
    """

    model: mujoco.MjModel
    spin: dict[str, Channel]
    steer: dict[str, Channel]
    imposed: bool
    statement: str


def servo_mode(model: mujoco.MjModel, a: int) -> str | None:
    """velocity, rate, position or None (a motor or anything else) for actuator ``a``."""
    fixed = int(model.actuator_gaintype[a]) == int(mujoco.mjtGain.mjGAIN_FIXED)
    affine = int(model.actuator_biastype[a]) == int(mujoco.mjtBias.mjBIAS_AFFINE)
    if not (fixed and affine):
        return None
    dyn = int(model.actuator_dyntype[a])
    kp, kv = -model.actuator_biasprm[a, 1], -model.actuator_biasprm[a, 2]
    if dyn == int(mujoco.mjtDyn.mjDYN_INTEGRATOR) and kp > 0:
        return "rate"
    if dyn == int(mujoco.mjtDyn.mjDYN_NONE):
        if kp > 0:
            return "position"
        if kp == 0 and kv > 0:
            return "velocity"
    return None


def _joint_actuators(model: mujoco.MjModel, joint: int) -> list[int]:
    return [a for a in range(model.nu) if model.actuator_trnid[a, 0] == joint and
            int(model.actuator_trntype[a]) == int(mujoco.mjtTrn.mjTRN_JOINT)]


def _channel(model: mujoco.MjModel, joint: int) -> Channel | None:
    for a in _joint_actuators(model, joint):
        mode = servo_mode(model, a)
        if mode is not None:
            return Channel(joint, a, mode, float(model.actuator_gear[a, 0]))
    return None


def _rolling(found: Wheels) -> list[AuditWheel]:
    return [w for w in found.wheels if w.kind in ROLLING_KINDS and w not in found.scrubbing]


def _own(model: mujoco.MjModel, found: Wheels) -> Drive | None:
    spin, steer = {}, {}
    for w in _rolling(found):
        if w.driven:
            ch = _channel(model, w.joint)
            if ch is None:
                return None
            spin[w.name] = ch
        if w.kind == "steerable":
            ch = _channel(model, w.steer_joint)
            if ch is None or ch.mode == "velocity":
                return None
            steer[w.name] = ch
    if not spin:
        return None
    label = mujoco.mjtObj.mjOBJ_ACTUATOR
    names = ", ".join(f"{mujoco.mj_id2name(model, label, c.actuator) or c.actuator} ({c.mode})"
                      for c in (*spin.values(), *steer.values()))
    return Drive(model, spin, steer, False, f"driven through its own servos: {names}")


def _touches(model: mujoco.MjModel, a: int, joints: set[int]) -> bool:
    trn, target = int(model.actuator_trntype[a]), int(model.actuator_trnid[a, 0])
    if trn == int(mujoco.mjtTrn.mjTRN_JOINT):
        return target in joints
    if trn == int(mujoco.mjtTrn.mjTRN_TENDON):
        adr, num = model.tendon_adr[target], model.tendon_num[target]
        return any(int(model.wrap_objid[w]) in joints for w in range(adr, adr + num)
                   if int(model.wrap_type[w]) == int(mujoco.mjtWrap.mjWRAP_JOINT))
    return False


def _name_joints(spec: mujoco.MjSpec, model: mujoco.MjModel, ids: list[int]) -> list[str]:
    names = []
    for j in ids:
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, j)
        if not name:
            name = f"audit_joint_{j}"
            spec.joints[j].name = name
        names.append(name)
    return names


def _impose(scene: Scene, found: Wheels) -> Drive:
    model = scene.model
    rolling = _rolling(found)
    steered = [w for w in rolling if w.kind == "steerable"]
    joints = {w.joint for w in rolling} | {w.steer_joint for w in steered}
    removed = [a for a in range(model.nu) if _touches(model, a, joints)]
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    full = np.zeros((model.nv, model.nv))
    mujoco.mj_fullM(model, data, full)
    mass = float(model.body_subtreemass[found.chassis])
    explicit = int(model.opt.integrator) not in _IMPLICIT
    spec = scene.spec.copy()
    for a in sorted(removed, reverse=True):
        spec.delete(spec.actuators[a])
    spin_names = _name_joints(spec, model, [w.joint for w in rolling])
    steer_names = _name_joints(spec, model, [w.steer_joint for w in steered])
    gains = []
    for w, jname in zip(rolling, spin_names, strict=True):
        mjj = full[model.jnt_dofadr[w.joint], model.jnt_dofadr[w.joint]]
        ieff = mass * w.radius ** 2 / len(rolling) + mjj
        act = spec.add_actuator(name=f"audit_spin_{jname}", target=jname,
                                trntype=mujoco.mjtTrn.mjTRN_JOINT)
        if explicit:  # a stiff velocity gain is unstable: track the integrated angle
            kp = min(ieff / SERVO_TAU ** 2, 0.5 * mjj / model.opt.timestep ** 2)
            kv = min(2.0 * ieff / SERVO_TAU, 0.5 * mjj / model.opt.timestep)
            act.set_to_position(kp=kp, kv=kv)
            gains.append(kp)
        else:
            kv = ieff / SERVO_TAU
            act.set_to_velocity(kv=kv)
            gains.append(kv)
    for w, jname in zip(steered, steer_names, strict=True):
        mss = full[model.jnt_dofadr[w.steer_joint], model.jnt_dofadr[w.steer_joint]]
        ieff = mss + mass * w.wheel.offset ** 2 + 1e-3 * mass * w.radius ** 2
        kp, kv = ieff / STEER_TAU ** 2, 2.0 * ieff / STEER_TAU
        if explicit:
            kv = min(kv, mss / model.opt.timestep)
        act = spec.add_actuator(name=f"audit_steer_{jname}", target=jname,
                                trntype=mujoco.mjtTrn.mjTRN_JOINT)
        act.set_to_position(kp=kp, kv=kv)
    compiled = spec.compile()
    mode = "position" if explicit else "velocity"
    spin = {w.name: Channel(w.joint, compiled.nu - len(rolling) - len(steered) + i,
                            mode, 1.0) for i, w in enumerate(rolling)}
    steer = {w.name: Channel(w.steer_joint, compiled.nu - len(steered) + i, "position", 1.0)
             for i, w in enumerate(steered)}
    gone = ", ".join(mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, a) or f"#{a}"
                     for a in removed)
    why = ("its wheel actuators are not velocity or position servos on the wheel joints"
           if removed else "no actuator drives its wheels")
    gain = (f"position servos on the integrated wheel angle (the model's integrator is "
            f"explicit, a stiff velocity gain would be unstable), kp {min(gains):.3g}-"
            f"{max(gains):.3g} N·m/rad" if explicit else
            f"velocity servos, kv {min(gains):.3g}-{max(gains):.3g} N·m·s/rad")
    statement = (f"driven through servos the audit imposed ({why}"
                 f"{'; removed: ' + gone if removed else ''}): {gain} on "
                 f"{', '.join(w.name for w in rolling)}"
                 + (f"; position servos on {', '.join(steer_names)}" if steered else ""))
    return Drive(compiled, spin, steer, True, statement)


def make_drive(scene: Scene, found: Wheels) -> Drive:
    """The robot's own servos if they can drive it, else imposed ones (module docstring)."""
    return _own(scene.model, found) or _impose(scene, found)
