"""Human-readable description of a robot: parameters, joints, actuators, mass, DoF."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import mujoco

from wmr_mujoco.lookup import load
from wmr_mujoco.models import classify
from wmr_mujoco.models.actuation import actuation_mode
from wmr_mujoco.models.builders.common import NUSER_ACTUATOR
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots import ROBOTS, RobotSpec, get_spec, registered

_JOINT_TYPES = {int(v): k.removeprefix("mjJNT_").lower()
                for k, v in mujoco.mjtJoint.__members__.items()}
_TRN_TYPES = {int(v): k.removeprefix("mjTRN_").lower()
              for k, v in mujoco.mjtTrn.__members__.items()}


def flatten_params(params: RobotParams | object, prefix: str = "") -> dict[str, object]:
    """Flatten a nested parameter dataclass into ``{"a.b": value}`` pairs.

    Raises:
        TypeError: ``params`` is not a dataclass instance.
    """
    out: dict[str, object] = {}
    for f in dataclasses.fields(params):
        value = getattr(params, f.name)
        if dataclasses.is_dataclass(value):
            out.update(flatten_params(value, f"{prefix}{f.name}."))
        else:
            out[f"{prefix}{f.name}"] = value
    return out


def used_params(params: RobotParams | object) -> dict[str, object]:
    """:func:`flatten_params` without the fields the robot's model does not use.

    A parameter dataclass names those in its ``UNUSED`` class attribute (dotted paths,
    e.g. ``"drive.steer_kp"`` for a robot without steering); a test checks, robot by
    robot, that changing them leaves the compiled model as it is.
    """
    unused = set(getattr(type(params), "UNUSED", ()))
    return {k: v for k, v in flatten_params(params).items() if k not in unused}


def _name(model: mujoco.MjModel, objtype: mujoco.mjtObj, i: int) -> str:
    return mujoco.mj_id2name(model, objtype, i) or f"#{i}"


def campion_line(model: mujoco.MjModel) -> str:
    """``Campion class: ...`` from the wheels found in ``model``, or why it has none."""
    try:
        return f"Campion class: {classify.summary(classify.classify(model))}"
    except ValueError as err:
        return f"Campion class: none ({err})"


def describe_file(path: Path) -> str:
    """``wmr info FILE.xml``: a foreign scene file described as a robot without builder.

    Raises:
        ValueError: ``path`` is not an existing file, or MuJoCo cannot read it (the
            message names the file, then MuJoCo's reason).
    """
    if not path.is_file():
        raise ValueError(f"MJCF file {str(path)!r} not found; give a robot name or an "
                         "existing .xml scene file")
    name, n = path.stem, 1
    while name in ROBOTS:  # a registered robot's own file: describe it beside, not over it
        name, n = f"{path.stem} (file {path.name}{'' if n == 1 else f' #{n}'})", n + 1
    spec = RobotSpec(name=name, description=f"model file {path.name}", params_type=None,
                     build=None, scene=path.resolve())
    with registered(spec):
        try:
            return describe(spec.name)
        except ValueError as err:  # MuJoCo's parser names the line, not the file
            reason = " ".join(str(err).split())
            raise ValueError(f"{path}: MuJoCo cannot read this file: {reason}") from None


def describe(robot: str) -> str:
    """Return the text printed by ``wmr info ROBOT``."""
    spec = get_spec(robot)
    model = load(robot)
    lines = [f"{spec.name}: {spec.description}", f"  scene file: {spec.scene_path}"]
    if spec.params_type is None:
        lines.append("parameters: none (a model file without a builder)")
    else:
        lines.append("parameters (SI units, radians):")
        lines += [f"  {k:<28} {v}" for k, v in used_params(spec.params_type()).items()]
    mass = float(model.body_mass[1:].sum())  # every body but the world
    lines.append(f"total mass: {mass:.4f} kg    degrees of freedom: {model.nv}    "
                 f"timestep: {model.opt.timestep:g} s    integrator: "
                 f"{mujoco.mjtIntegrator(model.opt.integrator).name.removeprefix('mjINT_')}")
    lines.append(campion_line(model))
    lines.append("joints:")
    for j in range(model.njnt):
        jtype = _JOINT_TYPES[int(model.jnt_type[j])]
        extra = ""
        if model.jnt_limited[j]:
            extra = f"  range [{model.jnt_range[j, 0]:g}, {model.jnt_range[j, 1]:g}]"
        lines.append(f"  {_name(model, mujoco.mjtObj.mjOBJ_JOINT, j):<22} {jtype:<6}"
                     f" body {_name(model, mujoco.mjtObj.mjOBJ_BODY, model.jnt_bodyid[j])}"
                     f"{extra}")
    if model.nu and spec.build is not None and model.nuser_actuator >= NUSER_ACTUATOR:
        lines.append(f"actuators (mode: {actuation_mode(model).value}; "
                     "switch with wmr_mujoco.set_actuation_mode):")
    elif model.nu:
        lines.append("actuators (the model's own, without rate/torque switching):")
    for a in range(model.nu):
        trn = _TRN_TYPES[int(model.actuator_trntype[a])]
        objtype = (mujoco.mjtObj.mjOBJ_TENDON if trn == "tendon" else mujoco.mjtObj.mjOBJ_JOINT)
        target = _name(model, objtype, model.actuator_trnid[a, 0])
        lo, hi = model.actuator_ctrlrange[a]
        flo, fhi = model.actuator_forcerange[a]
        torque = (f"torque [{flo:g}, {fhi:g}] N·m" if model.actuator_forcelimited[a]
                  else "torque unlimited")
        lines.append(f"  {_name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, a):<22} {trn} {target:<18}"
                     f" ctrl [{lo:g}, {hi:g}]  {torque}")
    if model.nkey:
        keys = ", ".join(_name(model, mujoco.mjtObj.mjOBJ_KEY, k) for k in range(model.nkey))
        lines.append(f"keyframes: {keys}")
    return "\n".join(lines)
