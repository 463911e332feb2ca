"""Builder of omni3's reduced rung: one capsule per wheel with anisotropic friction."""

from __future__ import annotations

import math

import numpy as np
from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.robots.omni3 import builder as full
from wmr_mujoco.robots.omni3.params import OmniParams

#: Friction coefficient along the wheel's axle, the direction the rollers let the wheel
#: roll sideways: a roller's rolling resistance. Against omni3's free rollers it is a
#: drag (``μ_lat N`` per wheel sliding sideways), but a lower one does not run: at 1e-3
#: and 3e-3 MuJoCo Warp (float32) diverged on a sideways translation and C MuJoCo's
#: Newton solver logged line searches whose "objective is not convex" (the elliptic cone
#: this flat is ill-conditioned). The ladder (:mod:`wmr_mujoco.bench.ladder`) measures
#: the drag against 1e-3 on C MuJoCo.
ROLLER_FRICTION = 0.01
#: Half-length of the capsule as a fraction of omni3's row offset e: its two end contacts
#: lie nearly in the wheel's mid-plane. Apart, they scrub against each other whenever the
#: platform turns (a yaw drag omni3's single touching roller does not have; the ladder's
#: design rows measure it at 0.1 e and e).
CAPSULE_ROW_FRACTION = 0.01
#: Least ``t_c/Δt`` of the capsule pairs' remedy. A capsule on the floor makes two
#: contacts (its end caps), nearly one above the other's point: the normal gain λ of
#: ``A (A + R)⁻¹ / d`` (stable while ``λ < t_c/Δt``, ``common.sliding_pair_kwargs``) is
#: twice omni3's one touching roller per wheel, 2.8 against 1.4 at rest
#: (``tests/models/builders/test_common.py`` computes it). At the wheels'
#: three steps the capsules bounced off the floor; four keep them on it (the random-steps
#: family, ``docs/floor-contact.md``), as mecanum4's four for its λ of 2.2.
CAPSULE_PAIR_STEPS = 4
WHEEL_RGBA = (0.55, 0.55, 0.58, 0.6)


def wheel_inertia(p: OmniParams) -> tuple[float, float, float]:
    """Mass, axial and diametral inertia of one wheel of omni3 lumped into one body.

    The hub (a cylinder of radius ``0.55 r``) plus ``2n`` rollers of mass ``m_r`` whose
    centres lie at distance ``d = r − b`` from the axle and ``±e`` along it, axes tangent
    to the rim (roller inertia ``i_ax`` about its axis, ``i_⊥`` across, as omni3's
    builder)::

        M    = m_hub + 2n m_r
        I_y  = m_hub ρ_h²/2 + 2n (m_r d² + i_⊥)                        (about the axle)
        I_x  = I_hub,⊥ + 2n (m_r (e² + d²/2) + (i_ax + i_⊥)/2)           (averaged over ζ)
    """
    r, n, m_r = p.wheel_radius, p.rollers_per_row, p.roller_mass
    d, s_max = full.roller_profile(p)
    b, e = p.roller_half_width, p.row_offset
    # Mean barrel radius over nine axial stations, as omni3's builder takes it.
    mean_rho = float(np.mean(np.sqrt(r * r - np.linspace(-s_max, s_max, 9) ** 2) - d))
    i_ax = 0.5 * m_r * mean_rho**2
    i_perp = m_r * (mean_rho**2 / 4.0 + (2.0 * s_max) ** 2 / 12.0)
    hub_r = 0.55 * r
    hub_w = full.HUB_WIDTH_FACTOR * 2.0 * (e + b)
    hub_diam = p.hub_mass * (hub_r**2 / 4 + hub_w**2 / 12)
    mass = p.hub_mass + 2 * n * m_r
    axial = p.hub_mass * hub_r**2 / 2 + 2 * n * (m_r * d * d + i_perp)
    diam = hub_diam + 2 * n * (m_r * (e * e + d * d / 2) + (i_ax + i_perp) / 2)
    return mass, axial, diam


def build(params: OmniParams, row_fraction: float = CAPSULE_ROW_FRACTION) -> mjcf.RootElement:
    """omni3 with each wheel one body on its hinge, carrying one capsule collider.

    Kinematic tree::

        world ─ platform [free joint; origin at the centre, wheel-centre height]
                 └─ wheel{1,2,3} [hinge about the axle] at α = 0°, 120°, 240°

    The platform, wheel poses, hinges (armature included), actuators and sensors are
    omni3's (:func:`wmr_mujoco.robots.omni3.builder.build`); each wheel's hub and
    rollers are one body (:func:`wheel_inertia`) whose collider is a capsule of radius r
    along the axle, touching the floor only through :func:`floor_pairs`. The solver is
    ``params.solver``.

    Args:
        params: omni3's parameters.
        row_fraction: the capsule's half-length as a fraction of the row offset e.
    """
    p = params
    r, L = p.wheel_radius, p.wheel_distance
    root = common.new_root("omni3_reduced", p.sim)
    if p.solver != "Newton":  # MuJoCo's default: the file says nothing
        root.option.solver = p.solver
    platform = root.worldbody.add("body", name="platform", pos=(0, 0, r))
    platform.add("freejoint", name="platform")
    m, R, t = p.platform_mass, p.platform_radius, full.PLATFORM_THICKNESS
    across = m * (R**2 / 4 + t**2 / 12)
    platform.add("inertial", pos=(0, 0, 0), mass=m, diaginertia=(across, across, m * R**2 / 2))
    platform.add("geom", dclass="visual", type="cylinder", size=(R, t / 2),
                 rgba=common.BODY_RGBA)
    platform.add("geom", dclass="visual", type="box", size=(0.6 * R, 0.01, 0.002),
                 pos=(0.4 * R, 0, t / 2), rgba=common.MARK_RGBA)
    site = platform.add("site", name="base", pos=(0, 0, 0))
    mass, axial, diam = wheel_inertia(p)
    width = p.row_offset + p.roller_half_width  # half-width of omni3's wheel (visual)
    for i in range(3):
        alpha = 2.0 * math.pi * i / 3.0
        yaw = alpha + math.pi / 2.0  # body x = drive direction, body y = axle (inward)
        name = f"wheel{i + 1}"
        wheel = platform.add("body", name=name,
                             pos=(L * math.cos(alpha), L * math.sin(alpha), 0.0),
                             quat=(math.cos(yaw / 2.0), 0.0, 0.0, math.sin(yaw / 2.0)))
        joint = wheel.add("joint", name=name, type="hinge", axis=(0, 1, 0),
                          armature=p.drive.wheel_armature)
        wheel.add("inertial", pos=(0, 0, 0), mass=mass, diaginertia=(diam, axial, diam))
        wheel.add("geom", name=f"{name}_collision", type="capsule",
                  size=(r, row_fraction * p.row_offset), zaxis=(0, 1, 0), contype=0,
                  conaffinity=0, group=3, mass=0)
        wheel.add("geom", dclass="visual", type="cylinder", size=(r, width), zaxis=(0, 1, 0),
                  rgba=WHEEL_RGBA)
        wheel.add("geom", dclass="visual", type="box", size=(0.9 * r, width + 0.001, 0.1 * r),
                  rgba=common.MARK_RGBA)
        common.add_wheel_actuator(root, name, p.drive, joint=joint)
    common.add_joint_sensors(root, [f"wheel{i + 1}" for i in range(3)])
    common.add_frame_sensors(root, site)
    return root


def floor_pairs(scene: mjcf.RootElement, params: OmniParams,
                roller_friction: float = ROLLER_FRICTION) -> None:
    """One floor pair per wheel capsule, friction ``(roller_friction, μ)`` on its tangents.

    MuJoCo's plane-capsule collider sets the contact frame's first tangent to the capsule
    axis (the axle, projected on the floor) and the second to ``normal × axle``, the drive
    direction; a pair's five friction values are (tangent 1, tangent 2, torsional,
    rolling, rolling). The capsule slides along its axle whenever the platform moves
    sideways, the sliding contact that lifts a wheel off the floor; with
    ``params.floor_impedance`` > 0 the pairs take the remedy
    (:func:`~wmr_mujoco.models.builders.common.sliding_pair_kwargs` at
    :data:`CAPSULE_PAIR_STEPS`, and the model's ``impratio``
    :func:`~wmr_mujoco.models.builders.common.sliding_impratio`); with 0 the collision
    class's contact (:func:`~wmr_mujoco.models.builders.common.contact_pair_kwargs`).
    """
    d = params.floor_impedance
    kwargs = common.sliding_pair_kwargs(params.sim, d, steps=CAPSULE_PAIR_STEPS)
    kwargs["friction"] = (roller_friction, params.sim.friction, *kwargs["friction"][2:])
    for i in range(3):
        scene.contact.add("pair", geom1="floor", geom2=f"wheel{i + 1}_collision", **kwargs)
    if d > 0.0:
        scene.option.impratio = common.sliding_impratio(d)
