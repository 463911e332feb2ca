"""Step commands on ``mecanum4``: the stick–slip dynamic model and its parameters.

:func:`step_platform` reads every parameter of
:class:`wmr_mujoco.robots.roller_wheels.roller_stick_slip.RollerPlatform` from the compiled model:
mass and yaw inertia (:func:`~wmr_mujoco.robots.roller_wheels.dynamics_from_model`),
wheel spin inertia with the rotor armature, the rate servo's gain and torque limit (the
actuator's user data and ``forcerange``), the contact friction (MuJoCo takes the larger of
the two geoms' coefficients) and the centre-of-mass height over the floor. The contact
rows are those of the colliders' effective layout
(:func:`wmr_mujoco.robots.mecanum4.collider.effective_layout`: the roller-pitch-averaged
angles γ̄ on the wheels the command turns, with the colliders' own rolling radius, angle
and lever), so that after the rise the model rolls as the kinematic model does.
:func:`step_acceleration_time` keeps the traction-only rise time
(:mod:`wmr_mujoco.robots.roller_wheels.roller_traction`) for comparison.
"""

from __future__ import annotations

import mujoco
import numpy as np

from wmr_mujoco.models.builders.common import NUSER_ACTUATOR
from wmr_mujoco.models.colliders import colliders, pair_with
from wmr_mujoco.robots.mecanum4 import collider
from wmr_mujoco.robots.mecanum4.builder import WHEEL_NAMES
from wmr_mujoco.robots.mecanum4.geometry import layout
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels import dynamics_from_model
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.roller_stick_slip import RollerPlatform
from wmr_mujoco.robots.roller_wheels.roller_traction import acceleration_time

#: Gravity, m/s².
GRAVITY = 9.81


def step_acceleration_time(model: mujoco.MjModel, params: MecanumParams,
                           twist: np.ndarray) -> float:
    """Least time to reach ``twist`` from rest with roller-axis forces ``|F_i| ≤ μ m g/4``."""
    lay = layout(params)
    dyn = dynamics_from_model(model, lay, "chassis", WHEEL_NAMES[0])
    loads = np.full(lay.n, dyn.mass * GRAVITY / lay.n)
    return acceleration_time(lay, dyn.mass, dyn.yaw_inertia, loads, params.sim.friction,
                             twist)


def drive_law(model: mujoco.MjModel, wheel: str) -> tuple[float, float]:
    """``(k_v, τ_max)`` of the rate servo on ``wheel``: user data and ``forcerange``.

    Raises:
        ValueError: the wheel has no actuator, or one without a symmetric force limit.
    """
    jid = model.joint(wheel).id
    acts = [a for a in range(model.nu) if model.actuator_trnid[a, 0] == jid]
    if len(acts) != 1:
        raise ValueError(f"wheel {wheel!r} has {len(acts)} actuators; expected one")
    a = acts[0]
    lo, hi = model.actuator_forcerange[a]
    if not model.actuator_forcelimited[a] or lo != -hi or hi <= 0:
        raise ValueError(f"wheel {wheel!r}: forcerange ({lo}, {hi}) is not a symmetric "
                         "limit ±τ_max")
    return float(model.actuator_user[a, :NUSER_ACTUATOR][2]), float(hi)


def contact_friction(model: mujoco.MjModel, wheel: str) -> float:
    """μ of a roller of ``wheel`` on the floor plane.

    The explicit ``<pair>``'s sliding friction if one names the two geoms, else MuJoCo's
    combination of the geoms' (the larger of the two: the rollers' priority 1 makes it
    theirs, and theirs is the floor's μ).
    """
    planes = [g for g in range(model.ngeom) if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_PLANE]
    rollers = [g for g in colliders(model) if model.geom_bodyid[g] != 0
               and (model.geom(g).name or "").startswith(wheel)]
    if not planes or not rollers:
        raise ValueError(f"wheel {wheel!r}: no roller collider or no floor plane in the model")
    pair = pair_with(model, planes[0], rollers[0])
    if pair is not None:
        return float(model.pair_friction[pair, 0])
    return float(max(model.geom_friction[planes[0], 0], model.geom_friction[rollers[0], 0]))


def com_height(model: mujoco.MjModel) -> float:
    """Height of the robot's centre of mass over the floor plane at the reference pose, m."""
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    mujoco.mj_comPos(model, data)
    root = int(model.body("chassis").rootid[0])
    floor = min(data.geom_xpos[g, 2] for g in range(model.ngeom)
                if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_PLANE)
    return float(data.subtree_com[root, 2] - floor)


def step_platform(model: mujoco.MjModel, params: MecanumParams, twist: np.ndarray,
                  load_transfer: bool = True) -> tuple[RollerPlatform, np.ndarray]:
    """The stick–slip model of ``mecanum4`` for a step to ``twist``, and its wheel command.

    Returns:
        ``(platform, ω_cmd)``: the model with the rows of
        :func:`~wmr_mujoco.robots.mecanum4.collider.effective_layout` (γ̄ on the wheels
        ``ω_cmd = H(γ) ν_cmd`` turns, and the colliders' own rolling radius, roller angle
        and contact lever), and ``ω_cmd``.
    """
    lay = layout(params)
    cmd = ok.wheel_jacobian(lay) @ np.asarray(twist, float)
    averaged = collider.effective_layout(params, twist)
    dyn = dynamics_from_model(model, lay, "chassis", WHEEL_NAMES[0])
    kv, tau_max = drive_law(model, WHEEL_NAMES[0])
    platform = RollerPlatform(
        averaged, dyn.mass, dyn.yaw_inertia, dyn.wheel_inertia, kv, tau_max,
        contact_friction(model, WHEEL_NAMES[0]),
        com_height(model) if load_transfer else 0.0, GRAVITY)
    return platform, cmd
