"""Builder of the four-mecanum-wheel platform with passive rollers on free hinges.

The roller colliders follow the ideal mecanum profile of
:mod:`wmr_mujoco.robots.mecanum4.roller` (derivation in ``docs/mecanum.md``).
"""

from __future__ import annotations

import math

import numpy as np
from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.robots.mecanum4 import roller as mr
from wmr_mujoco.robots.mecanum4.params import MecanumParams

CHASSIS_HEIGHT = 0.04
HUB_RADIUS_FACTOR = 0.6
#: Profile mesh resolution: rings along the roller axis, vertices around each ring.
PROFILE_RINGS = 17
PROFILE_SEGMENTS = 40
CAPSULE_RADIUS_FACTOR = 0.8
ROLLER_RGBA = (0.55, 0.55, 0.58, 1.0)
ROLLER_MARK_RGBA = (0.9, 0.3, 0.1, 1.0)
#: Visual drive of each wheel (fractions of the wheel radius R): gear-motor radius (it
#: stands out above and below the chassis) and length, axle radius.
MOTOR_RADIUS = 0.5
MOTOR_LENGTH = 1.2
AXLE_RADIUS = 0.12

#: Wheels: name, x sign, y sign, roller-angle sign (γ_i = sign · roller_angle).
#: Layout "O" on the floor: FL −γ, FR +γ, RL +γ, RR −γ, as
#: :func:`wmr_mujoco.robots.roller_wheels.omni_kinematics.mecanum_layout`.
WHEELS = (("wheel_fl", 1.0, 1.0, -1.0), ("wheel_fr", 1.0, -1.0, 1.0),
          ("wheel_rl", -1.0, 1.0, 1.0), ("wheel_rr", -1.0, -1.0, -1.0))
WHEEL_NAMES = tuple(w[0] for w in WHEELS)


def roller_axis_span(params: MecanumParams) -> float:
    """``t_m``: half-length of the roller axis segment whose spheres cover ±φ_m."""
    p = params
    return float(mr.axis_parameter(p.wheel_radius, p.roller_half_width, p.roller_angle,
                                   p.roller_half_span))


def profile_vertices(params: MecanumParams) -> np.ndarray:
    """Vertices of the convex ideal roller, axis along z: rings of the meridian (σ, ρ)."""
    p = params
    t = np.linspace(-1.0, 1.0, PROFILE_RINGS) * roller_axis_span(p)
    sigma, rho = mr.ideal_profile(p.wheel_radius, p.roller_half_width, p.roller_angle, t)
    ang = 2.0 * np.pi * np.arange(PROFILE_SEGMENTS) / PROFILE_SEGMENTS
    verts = [(rk * math.cos(a), rk * math.sin(a), sk)
             for sk, rk in zip(sigma, rho, strict=True) for a in ang]
    return np.round(np.asarray(verts), 9)


def roller_geom_kwargs(params: MecanumParams) -> dict:
    """Type and size of one roller's collider (axis along the roller body's z)."""
    p = params
    R, b, g = p.wheel_radius, p.roller_half_width, p.roller_angle
    shape = p.roller_shape
    if shape == "profile":
        return {"type": "mesh", "mesh": "roller_profile"}
    if shape == "ellipsoid":
        return {"type": "ellipsoid", "size": (b, b, mr.ellipsoid_semi_axis(R, b, g))}
    if shape == "capsule":
        # Cap spheres of radius ρ_c centred on the axis where λ(t_c) = R − q(t_c) = ρ_c,
        # so that they touch the envelope: t_c = √((R − ρ_c)² − d²) / c.
        rho_c = CAPSULE_RADIUS_FACTOR * b
        d = p.axis_distance
        t_c = math.sqrt((R - rho_c) ** 2 - d * d) / math.cos(g)
        return {"type": "capsule", "size": (rho_c, min(t_c, roller_axis_span(p)))}
    return {"type": "sphere", "size": (b,)}


def _frame_quat(z_axis: np.ndarray, x_axis: np.ndarray) -> tuple[float, ...]:
    """Quaternion (w, x, y, z) of the frame with the given orthonormal x and z axes."""
    y_axis = np.cross(z_axis, x_axis)
    m = np.column_stack([x_axis, y_axis, z_axis])
    w = math.sqrt(max(1.0 + m[0, 0] + m[1, 1] + m[2, 2], 1e-12)) / 2.0
    if w > 1e-3:
        q = (w, (m[2, 1] - m[1, 2]) / (4 * w), (m[0, 2] - m[2, 0]) / (4 * w),
             (m[1, 0] - m[0, 1]) / (4 * w))
    else:  # rotation by π: use the largest diagonal term
        import mujoco  # local: only this corner case needs it
        out = np.zeros(4)
        mujoco.mju_mat2Quat(out, m.ravel())
        q = tuple(out)
    return tuple(float(round(v, 12)) for v in q)


def _add_wheel(chassis: mjcf.Element, root: mjcf.RootElement, params: MecanumParams,
               name: str, sx: float, sy: float, sg: float) -> None:
    p = params
    R, b, d = p.wheel_radius, p.roller_half_width, p.axis_distance
    wheel = chassis.add("body", name=name, pos=(sx * p.half_length, sy * p.half_track, 0.0))
    joint = wheel.add("joint", name=name, type="hinge", axis=(0, 1, 0),
                      armature=p.drive.wheel_armature)
    hub_r, hub_w = HUB_RADIUS_FACTOR * R, 1.2 * p.wheel_half_width
    common.add_hub(wheel, p.hub_mass, hub_r, hub_w)
    c, s = math.cos(p.roller_angle), sg * math.sin(p.roller_angle)
    t_m = roller_axis_span(p)
    sig, rho = mr.ideal_profile(R, b, p.roller_angle, np.linspace(-t_m, t_m, 9))
    mean_rho, half_len = float(np.mean(rho)), float(sig[-1])
    # Roller inertia: a solid of revolution ≈ cylinder of the mean radius and length 2σ_m.
    i_axis = 0.5 * p.roller_mass * mean_rho**2
    i_perp = p.roller_mass * (mean_rho**2 / 4.0 + (2.0 * half_len) ** 2 / 12.0)
    geom = roller_geom_kwargs(p)
    n = p.rollers_per_wheel
    for k in range(n):
        zeta = 2.0 * math.pi * k / n  # wheel angle of the roller, from the bottom
        # Rotation about the wheel's y by ζ: (x, z) → (x cos ζ + z sin ζ, −x sin ζ + z cos ζ).
        cz, sz = math.cos(zeta), math.sin(zeta)
        centre = np.array([-d * sz, 0.0, -d * cz])
        axis = np.array([c * cz, s, -c * sz])
        radial = np.array([-sz, 0.0, -cz])  # outward, perpendicular to the axis
        rname = f"{name}_roller{k:02d}"
        roller = wheel.add("body", name=rname, pos=tuple(float(round(v, 12)) for v in centre),
                           quat=_frame_quat(axis, radial))
        roller.add("joint", name=rname, dclass="roller")
        roller.add("inertial", pos=(0, 0, 0), mass=p.roller_mass,
                   diaginertia=(i_perp, i_perp, i_axis))
        roller.add("geom", name=f"{rname}_collision", dclass="roller", **geom)
        roller.add("geom", dclass="visual", rgba=ROLLER_RGBA, **geom)
        # A stripe along the roller makes its spin visible.
        roller.add("geom", dclass="visual", type="box",
                   size=(0.25 * b, 0.25 * b, 0.4 * half_len), pos=(0.8 * b, 0, 0),
                   rgba=ROLLER_MARK_RGBA)
    common.add_wheel_actuator(root, name, p.drive, joint=joint)


def _add_drive_visuals(chassis: mjcf.Element, params: MecanumParams, sx: float,
                       sy: float) -> None:
    """Gear motor in the chassis side and the axle through the hub of wheel (sx, sy)."""
    p = params
    R, x = p.wheel_radius, sx * p.half_length
    motor_out = p.half_track - p.wheel_half_width - 0.002  # clear of the rollers
    axle_end = p.half_track + p.wheel_half_width + 0.003

    def point(y: float) -> tuple[float, float, float]:
        return (x, sy * y, 0.0)

    common.add_drive_mount(chassis, point(motor_out - MOTOR_LENGTH * R), point(motor_out),
                           point(axle_end), MOTOR_RADIUS * R, AXLE_RADIUS * R)


def roller_collider_names(params: MecanumParams) -> list[str]:
    """Names of every roller collider, wheel by wheel, as :func:`build` names them."""
    return [f"{wheel}_roller{k:02d}_collision" for wheel in WHEEL_NAMES
            for k in range(params.rollers_per_wheel)]


def floor_pairs(scene: mjcf.RootElement, params: MecanumParams) -> None:
    """One contact pair of every roller collider with the scene's ``floor`` (``scene_extras``).

    The same contact set as contact bits gave: with bits, the rollers (``contype`` 0,
    ``conaffinity`` 1) could touch only a geom of ``contype`` 1, i.e. never each other,
    and no other robot geom collides, so in this scene the 4 n pairs roller–floor list
    every contact bits could ever make. Each pair
    carries what MuJoCo's combination of the two geoms gives
    (:func:`~wmr_mujoco.models.builders.common.contact_pair_kwargs`), so the physics is
    the same (tested step for step against the bit-filtered model). Cheaper: with no
    bits set, the broadphase bounds no roller body, and each step tests the 4 n pairs
    directly instead of sorting 4 n + 1 bodies' boxes.
    With ``floor_impedance`` > 0 the pairs carry the remedy of
    :func:`~wmr_mujoco.models.builders.common.sliding_pair_kwargs`.
    """
    kwargs = common.sliding_pair_kwargs(params.sim, params.floor_impedance)
    for name in roller_collider_names(params):
        scene.contact.add("pair", geom1="floor", geom2=name, **kwargs)


def build(params: MecanumParams) -> mjcf.RootElement:
    """Four-mecanum-wheel platform on a free joint.

    Kinematic tree::

        world ─ chassis [free joint; origin at the centre, wheel-centre height]
                 └─ wheel_{fl,fr,rl,rr} [hinge about the axle, +y] at (±a, ±w)
                      └─ wheel_xx_roller{kk} [free hinge about the roller axis]

    Every wheel body is aligned with the chassis (x forward, y left), so a positive wheel
    rate drives along +x; the contact roller of wheel i has its axis at ``γ_i`` from +x
    (FL −γ, FR +γ, RL +γ, RR −γ): ``θ̇ = H ν`` with Lynch & Park's formula
    (:func:`wmr_mujoco.robots.roller_wheels.omni_kinematics.mecanum_layout`).
    """
    p = params
    R = p.wheel_radius
    root = common.new_root("mecanum4", p.sim)
    root.option.solver = p.solver
    if p.jacobian != "auto":  # MuJoCo's default: the file says nothing
        root.option.jacobian = p.jacobian
    root.option.cone = p.cone
    if p.floor_impedance > 0.0:
        root.option.impratio = common.sliding_impratio(p.floor_impedance)
    roller = common.add_roller_default(root, p.sim, p.roller_damping, p.roller_armature)
    roller.joint.frictionloss = 0.0
    # No contact bits: the scene's explicit pairs (floor_pairs) make the roller contacts,
    # and the broadphase skips the 64 roller bodies.
    roller.geom.conaffinity = 0
    if p.roller_shape == "profile":
        root.asset.add("mesh", name="roller_profile", vertex=profile_vertices(p).ravel())
    chassis = root.worldbody.add("body", name="chassis", pos=(0, 0, R))
    chassis.add("freejoint", name="chassis")
    inner = p.half_track - p.wheel_half_width - 0.005
    size = (2.0 * p.half_length + R, 2.0 * inner, CHASSIS_HEIGHT)
    chassis.add("inertial", pos=(0, 0, 0), mass=p.chassis_mass,
                diaginertia=common.box_inertia(p.chassis_mass, size))
    common.add_box_body_geoms(chassis, size)
    chassis.add("geom", dclass="visual", type="box", size=(0.3 * size[0], 0.01, 0.002),
                pos=(0.2 * size[0], 0, CHASSIS_HEIGHT / 2), rgba=common.MARK_RGBA)
    site = chassis.add("site", name="base", pos=(0, 0, 0))
    for name, sx, sy, sg in WHEELS:
        _add_drive_visuals(chassis, p, sx, sy)
        _add_wheel(chassis, root, p, name, sx, sy, sg)
    common.add_joint_sensors(root, list(WHEEL_NAMES))
    common.add_frame_sensors(root, site)
    return root
