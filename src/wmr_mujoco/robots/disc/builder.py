"""Builder of the single steerable disc (lecture section 1), mounted or free."""

from __future__ import annotations

import numpy as np
from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.robots.disc.params import DiscParams

#: Steering of the mounted disc is unlimited in angle; this bounds the integrated
#: target of the steering-rate servo only.
STEER_RANGE = 1000.0
#: Initial speeds of the free-disc keyframes, m/s, and its spin rate, rad/s.
FREE_ROLL_SPEED = 1.0
FREE_SPIN_RATE = 15.0
FREE_LEAN = 0.15


def build(params: DiscParams) -> mjcf.RootElement:
    """Disc on a steering mount that keeps the wheel plane vertical.

    Kinematic tree::

        world ─ carriage [slides x, y, z; hinge steer about z] ─ wheel [hinge about y]

    The slides are frictionless and unactuated: the carriage moves horizontally only
    through the wheel's contact with the floor, and its weight rests on the wheel.
    Inputs (lecture): wheel spin θ̇ with ``v = R θ̇`` and steering rate ``ω = φ̇``.
    """
    p = params
    r = p.wheel.radius
    root = common.new_root("disc", p.sim)
    root.option.impratio = p.floor_impratio
    carriage = root.worldbody.add("body", name="carriage", pos=(0, 0, r))
    for axis_name, axis in (("x", (1, 0, 0)), ("y", (0, 1, 0)), ("z", (0, 0, 1))):
        carriage.add("joint", name=f"mount_{axis_name}", type="slide", axis=axis)
    steer = carriage.add("joint", name="steer", type="hinge", axis=(0, 0, 1))
    size = (0.06, 0.04, 0.04)
    carriage.add("inertial", pos=(0, 0, 0), mass=p.mount_mass,
                 diaginertia=common.box_inertia(p.mount_mass, size))
    # A fork from the axle over the disc to the steering head on top.
    common.add_fork(carriage, p.wheel, tops=((0.0, 1.05 * r),))
    carriage.add("geom", dclass="visual", type="box",
                 size=(0.01, 0.005, 0.12 * r), pos=(0, 0, 1.12 * r),
                 rgba=common.BODY_RGBA)
    site = carriage.add("site", name="base", pos=(0, 0, 0))
    common.add_wheel(carriage, "wheel", p.wheel, pos=(0, 0, 0),
                     armature=p.drive.wheel_armature)
    common.add_wheel_actuator(root, "wheel", p.drive, joint="wheel")
    common.add_steer_actuator(root, "steer", steer, p.drive, STEER_RANGE)
    common.add_joint_sensors(root, ["wheel"], ["steer"])
    common.add_frame_sensors(root, site)
    return root


def floor_pair(scene: mjcf.RootElement, params: DiscParams) -> None:
    """The mounted wheel's contact pair with the scene's ``floor`` (a ``scene_extras``).

    A frictional soft contact in its cone state pushes the wheel off the floor while it
    slides: the normal row's acceleration balance gains ``μ d (ṡ + B_f s)`` for slip
    ``s`` and friction reference damping ``B_f`` (docs/rolling-disc.md), against the
    weight's ``(1 − d) g``. With the geoms' default contact (``d`` ≈ 0.95,
    ``B_f = 2/t_c``) that is hundreds of m/s² at a slip of 1 m/s, and the wheel hops.
    This pair keeps the normal row's dynamics (``solref`` time constant and critical
    damping, which MuJoCo scales by ``1/d``) and sets:

    * ``solimp`` ``d0 = d_width = d`` (:attr:`DiscParams.floor_impedance`);
    * ``solreffriction`` damping ``B_f = 1/Δt`` in MuJoCo's direct form (``−B_f d``,
      which MuJoCo divides by ``d``): gripping friction removes the slip within one
      step, like the geoms' ``2/t_c`` with ``t_c = 2 Δt``, while the push
      ``μ d B_f s = μ d s/Δt`` stays under ``g`` up to a slip of ``g Δt/(μ d)``.
    """
    p = params
    d = p.floor_impedance
    mu = p.sim.friction
    scene.contact.add("pair", geom1="wheel_collision", geom2="floor", condim=3,
                      friction=(mu, mu, 0.005, 0.0001, 0.0001),
                      solref=(p.sim.contact_timeconst, 1.0),
                      solimp=(d, d, 0.001, 0.5, 2.0),
                      solreffriction=(0.0, -d / p.sim.timestep))


def _quat_about(axis: tuple[float, float, float], angle: float) -> np.ndarray:
    half = 0.5 * angle
    return np.concatenate([[np.cos(half)], np.sin(half) * np.asarray(axis, float)])


def build_free(params: DiscParams) -> mjcf.RootElement:
    """Free disc: the same wheel on a free joint, no mount and no actuators.

    Its own integrator, timestep and collision rim (``DiscParams.free_*``): the
    settings the fidelity study (``python -m wmr_mujoco.bench.disc_study``) found cheapest
    that meet the rolling-disc targets.

    Keyframes (free-joint ``qvel`` is world linear velocity then body angular
    velocity; the disc axle is the body y axis):

    * ``rest``: upright, at rest.
    * ``rolling``: upright, rolling along +x at ``FREE_ROLL_SPEED``:
      ``v = (V, 0, 0)``, ``ω_body = (0, V/R, 0)``.
    * ``spinning``: upright, spinning about the vertical diameter at
      ``FREE_SPIN_RATE`` (a spinning coin).
    * ``leaning``: leaning by ``FREE_LEAN`` rad about the rolling direction while
      rolling at ``FREE_ROLL_SPEED``; contact point on the floor, so it curves.
    """
    p = params
    r = p.wheel.radius
    root = common.new_root("disc_free", p.sim)
    root.option.integrator = p.free_integrator
    root.option.timestep = p.free_timestep
    root.size.nuser_actuator = 0
    body = root.worldbody.add("body", name="disc", pos=(0, 0, r))
    body.add("freejoint", name="disc")
    site = body.add("site", name="base", pos=(0, 0, 0))
    common.add_wheel_geoms(body, "disc", p.wheel)
    # Thin rim: the collision ellipsoid (R, rim, R) touches a leaning floor where a thin
    # disc would (DiscParams.free_rim); the inertia stays the full wheel's.
    body.find("geom", "disc_collision").size = (r, p.free_rim, r)
    common.add_frame_sensors(root, site)
    up = (0.0, 0.0, r)
    spin = FREE_ROLL_SPEED / r
    lean_quat = _quat_about((1.0, 0.0, 0.0), FREE_LEAN)
    lean_z = np.hypot(r * np.cos(FREE_LEAN), p.free_rim * np.sin(FREE_LEAN))
    keys = {
        "rest": (up, (1, 0, 0, 0), (0, 0, 0), (0, 0, 0)),
        "rolling": (up, (1, 0, 0, 0), (FREE_ROLL_SPEED, 0, 0), (0, spin, 0)),
        "spinning": (up, (1, 0, 0, 0), (0, 0, 0), (0, 0, FREE_SPIN_RATE)),
        "leaning": ((0, 0, lean_z), lean_quat, (FREE_ROLL_SPEED, 0, 0),
                    (0, spin, 0)),
    }
    for name, (pos, quat, lin, ang) in keys.items():
        root.keyframe.add("key", name=name, qpos=np.concatenate([pos, quat]),
                          qvel=np.concatenate([lin, ang]))
    return root
