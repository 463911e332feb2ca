"""Builder of the three-omni-wheel robot with passive barrel rollers (lecture §4)."""

from __future__ import annotations

import math

import numpy as np
from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.robots.omni3.params import OmniParams

#: Platform height above the wheel centres (visual) and thickness (inertia).
PLATFORM_THICKNESS = 0.03
HUB_WIDTH_FACTOR = 0.6
#: Barrel mesh resolution: rings along the roller axis, vertices around each ring.
BARREL_RINGS = 17
BARREL_SEGMENTS = 48
ROLLER_RGBA = (0.55, 0.55, 0.58, 1.0)
ROLLER_MARK_RGBA = (0.9, 0.3, 0.1, 1.0)
MOTOR_RGBA = common.MOTOR_RGBA
METAL_RGBA = common.METAL_RGBA
#: Visual drive of each wheel (fractions of the wheel radius r): gear-motor radius and
#: length, axle radius; mounting plate thickness, m.
MOTOR_RADIUS = 0.35
MOTOR_LENGTH = 0.8
AXLE_RADIUS = 0.12
PLATE_THICKNESS = 0.004


def _add_drive_visuals(platform: mjcf.Element, params: OmniParams, alpha: float) -> None:
    """Add what holds the wheel at angle α: a plate, its gear motor and the axle.

    The plate stands at the platform's rim, the motor passes through it, and the axle
    runs from the motor through the hub. Visual only (no mass, no contact) and fixed to
    the platform, so the hub turns about the axle.
    """
    p = params
    r, L = p.wheel_radius, p.wheel_distance
    u = np.array([math.cos(alpha), math.sin(alpha), 0.0])  # radial: the wheel's axle
    inner = L - (p.row_offset + p.roller_half_width) - 0.002  # the wheel's inner face
    motor_out = inner - 0.002
    motor_in = motor_out - MOTOR_LENGTH * r

    axle_end = L + p.row_offset + p.roller_half_width + 0.003
    common.add_drive_mount(platform, motor_in * u, motor_out * u, axle_end * u,
                           MOTOR_RADIUS * r, AXLE_RADIUS * r)
    half = (PLATE_THICKNESS / 2.0, 1.1 * MOTOR_RADIUS * r,
            0.5 * (PLATFORM_THICKNESS + 1.1 * MOTOR_RADIUS * r))
    plate_r = min(p.platform_radius + half[0], motor_out - half[0])
    centre = plate_r * u + np.array([0.0, 0.0, half[2] - PLATFORM_THICKNESS / 2.0])
    platform.add("geom", dclass="visual", type="box", size=half, pos=tuple(centre),
                 quat=(math.cos(alpha / 2.0), 0.0, 0.0, math.sin(alpha / 2.0)),
                 rgba=METAL_RGBA)


def roller_profile(params: OmniParams) -> tuple[float, float]:
    """``(d, s_max)``: roller axis distance from the wheel centre and the half-length.

    The ideal barrel's radius at axial position s is ``ρ(s) = √(r² − s²) − d`` with
    ``d = r − b``: its outer edge then lies on the sphere of radius r about the wheel
    centre. A roller covering wheel rotations ±δ extends to ``s_max = r sin δ``.
    """
    r = params.wheel_radius
    return r - params.roller_half_width, r * math.sin(params.roller_half_span)


def barrel_vertices(params: OmniParams) -> np.ndarray:
    """Vertices of the convex barrel, axis along z: rings of the exact profile ρ(s)."""
    r = params.wheel_radius
    d, s_max = roller_profile(params)
    s = np.linspace(-s_max, s_max, BARREL_RINGS)
    rho = np.sqrt(r * r - s * s) - d
    ang = 2.0 * np.pi * np.arange(BARREL_SEGMENTS) / BARREL_SEGMENTS
    verts = [(rk * math.cos(a), rk * math.sin(a), sk) for sk, rk in zip(s, rho, strict=True)
             for a in ang]
    return np.round(np.asarray(verts), 9)


def _add_roller_geoms(body: mjcf.Element, params: OmniParams, name: str) -> None:
    """Collision geom of one roller (axis along the body's z) and its visual twin."""
    r = params.wheel_radius
    b = params.roller_half_width
    d, s_max = roller_profile(params)
    shape = params.roller_shape
    if shape == "barrel":
        kwargs = {"type": "mesh", "mesh": "barrel"}
    elif shape == "ellipsoid":
        # Semi-axis a matched to the barrel's curvature at its middle: a² = b r.
        kwargs = {"type": "ellipsoid", "size": (b, b, math.sqrt(b * r))}
    elif shape == "capsule":
        # End caps of radius ρ_c centred on the sphere of radius r − ρ_c.
        rho_c = 0.8 * b
        half = math.sqrt(max((r - rho_c) ** 2 - d * d, 1e-12))
        kwargs = {"type": "capsule", "size": (rho_c, min(half, s_max))}
    else:  # sphere
        kwargs = {"type": "sphere", "size": (b,)}
    body.add("geom", name=name, dclass="roller", **kwargs)
    body.add("geom", dclass="visual", rgba=ROLLER_RGBA, **kwargs)


def _add_wheel(platform: mjcf.Element, root: mjcf.RootElement, params: OmniParams,
               index: int) -> None:
    p = params
    r, L = p.wheel_radius, p.wheel_distance
    alpha = 2.0 * math.pi * index / 3.0
    yaw = alpha + math.pi / 2.0  # body x = drive direction, body y = axle (inward)
    name = f"wheel{index + 1}"
    wheel = platform.add("body", name=name, pos=(L * math.cos(alpha), L * math.sin(alpha), 0.0),
                         quat=(math.cos(yaw / 2.0), 0.0, 0.0, math.sin(yaw / 2.0)))
    joint = wheel.add("joint", name=name, type="hinge", axis=(0, 1, 0),
                      armature=p.drive.wheel_armature)
    hub_r, hub_w = 0.55 * r, HUB_WIDTH_FACTOR * 2.0 * (p.row_offset + p.roller_half_width)
    common.add_hub(wheel, p.hub_mass, hub_r, hub_w)
    d, s_max = roller_profile(p)
    n = p.rollers_per_row
    b = p.roller_half_width
    mean_rho = float(np.mean(np.sqrt(r * r - np.linspace(-s_max, s_max, 9) ** 2) - d))
    # Roller inertia: a solid of revolution ≈ cylinder of the mean radius and length 2 s_max.
    i_axis = 0.5 * p.roller_mass * mean_rho**2
    i_perp = p.roller_mass * (mean_rho**2 / 4.0 + (2.0 * s_max) ** 2 / 12.0)
    for row, side in enumerate((1.0, -1.0)):
        for k in range(n):
            zeta = 2.0 * math.pi * k / n + row * math.pi / n  # position around the axle
            beta = zeta + math.pi / 2.0  # rotate body z onto the tangent (cos ζ, 0, −sin ζ)
            rname = f"{name}_roller{row}{k}"
            roller = wheel.add(
                "body", name=rname,
                pos=(d * math.sin(zeta), side * p.row_offset, d * math.cos(zeta)),
                quat=(math.cos(beta / 2.0), 0.0, math.sin(beta / 2.0), 0.0))
            roller.add("joint", name=rname, dclass="roller")
            roller.add("inertial", pos=(0, 0, 0), mass=p.roller_mass,
                       diaginertia=(i_perp, i_perp, i_axis))
            _add_roller_geoms(roller, p, f"{rname}_collision")
            # A stripe along the roller makes its spin visible.
            roller.add("geom", dclass="visual", type="box", size=(0.25 * b, 0.25 * b, 0.4 * s_max),
                       pos=(0.8 * b, 0, 0), rgba=ROLLER_MARK_RGBA)
    common.add_wheel_actuator(root, name, p.drive, joint=joint)


def roller_collider_names(params: OmniParams) -> list[str]:
    """Names of every roller collider, wheel by wheel and row by row (as :func:`build`)."""
    return [f"wheel{i + 1}_roller{row}{k}_collision" for i in range(3) for row in range(2)
            for k in range(params.rollers_per_row)]


def floor_pairs(scene: mjcf.RootElement, params: OmniParams, plain: bool = False) -> None:
    """With ``floor_impedance`` > 0, a contact pair of every roller collider with the floor.

    A ``scene_extras``: the contact set contact bits give (the rollers touch the floor
    only), each pair with the remedy of
    :func:`~wmr_mujoco.models.builders.common.sliding_pair_kwargs`; cheaper, since the
    broadphase then bounds no roller body. ``plain=True`` gives the collision class's
    contact instead (the same physics as the bits; what the cost study times). With
    ``floor_impedance`` 0 the rollers keep their contact bits, which
    :func:`~wmr_mujoco.validation.omni_wheels.hybrid_from_model` reads the rollers and
    their contact from.
    """
    if params.floor_impedance == 0.0 and not plain:
        return
    kwargs = (common.contact_pair_kwargs(params.sim) if plain
              else common.sliding_pair_kwargs(params.sim, params.floor_impedance))
    for name in roller_collider_names(params):
        scene.contact.add("pair", geom1="floor", geom2=name, **kwargs)


def build(params: OmniParams) -> mjcf.RootElement:
    """Three-omni-wheel platform on a free joint.

    Kinematic tree::

        world ─ platform [free joint; origin at the centre, wheel-centre height]
                 └─ wheel{1,2,3} [hinge about the axle] at α = 0°, 120°, 240°
                      └─ wheel{i}_roller{row}{k} [free hinge about the roller axis]

    Wheel i's body x axis is its drive direction (−sin α_i, cos α_i), so a positive wheel
    rate moves the platform as ``θ̇ = (1/r) J ν`` (see ``docs/analytical.md``).
    """
    p = params
    r = p.wheel_radius
    root = common.new_root("omni3", p.sim)
    if p.solver != "Newton":  # MuJoCo's default: the file says nothing
        root.option.solver = p.solver
    if p.jacobian != "auto":  # MuJoCo's default: the file says nothing
        root.option.jacobian = p.jacobian
    root.option.cone = p.cone
    roller = common.add_roller_default(root, p.sim, p.roller_damping, p.roller_armature)
    if p.floor_impedance > 0.0:
        # The scene's explicit pairs (floor_pairs) make the roller contacts, and with no
        # contact bits the broadphase bounds none of the roller bodies (cheaper). The
        # rollers take the pairs' solimp and solref, from which the hybrid model
        # (roller_wheels.model_info.hybrid_from_model) reads their contact.
        pair = common.sliding_pair_kwargs(p.sim, p.floor_impedance)
        roller.geom.solimp, roller.geom.solref = pair["solimp"], pair["solref"]
        roller.geom.conaffinity = 0
        root.option.impratio = common.sliding_impratio(p.floor_impedance)
    if p.roller_shape == "barrel":
        root.asset.add("mesh", name="barrel", vertex=barrel_vertices(p).ravel())
    platform = root.worldbody.add("body", name="platform", pos=(0, 0, r))
    platform.add("freejoint", name="platform")
    m, R = p.platform_mass, p.platform_radius
    platform.add("inertial", pos=(0, 0, 0), mass=m,
                 diaginertia=(m * (R**2 / 4 + PLATFORM_THICKNESS**2 / 12),
                              m * (R**2 / 4 + PLATFORM_THICKNESS**2 / 12), m * R**2 / 2))
    platform.add("geom", dclass="visual", type="cylinder", size=(R, PLATFORM_THICKNESS / 2),
                 rgba=common.BODY_RGBA)
    platform.add("geom", dclass="visual", type="box", size=(0.6 * R, 0.01, 0.002),
                 pos=(0.4 * R, 0, PLATFORM_THICKNESS / 2), rgba=common.MARK_RGBA)
    site = platform.add("site", name="base", pos=(0, 0, 0))
    for i in range(3):
        _add_drive_visuals(platform, p, 2.0 * math.pi * i / 3.0)
        _add_wheel(platform, root, p, i)
    common.add_joint_sensors(root, [f"wheel{i + 1}" for i in range(3)])
    common.add_frame_sensors(root, site)
    return root
