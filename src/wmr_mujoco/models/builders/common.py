"""Pieces shared by every robot builder: root defaults, wheels, actuators, XML export.

Conventions (all robots):
    * World frame: x forward at the initial pose, y left, z up; floor at z = 0.
    * Every wheel body has its spin hinge along its local +y axis, so a positive
      wheel rate θ̇ rolls the wheel forward along its local +x at ``v = R θ̇``.
    * Geoms use two default classes, ``visual`` (group 2, no contact, no mass) and
      ``collision`` (group 3); inertia always comes from explicit ``<inertial>``
      elements so the documented masses are exact.
    * Actuators carry ``user = [kind, kp, kv, rate_limit]`` so that
      :func:`wmr_mujoco.models.actuation.set_actuation_mode` can switch a compiled model
      between servo and torque control without the XML.
"""

from __future__ import annotations

from collections.abc import Sequence

from dm_control import mjcf
from lxml import etree

from wmr_mujoco.models.params import DriveParams, SimParams, WheelParams
from wmr_mujoco.models.solids import box_inertia  # noqa: F401  (re-exported)

#: Actuator ``user[0]`` codes.
KIND_WHEEL = 0
KIND_STEER = 1
#: Number of ``user`` values per actuator.
NUSER_ACTUATOR = 4
#: Significant digits written to the checked-in XML.
XML_PRECISION = 12

WHEEL_RGBA = (0.15, 0.15, 0.17, 1.0)
MARK_RGBA = (0.95, 0.75, 0.1, 1.0)
BODY_RGBA = (0.2, 0.45, 0.8, 1.0)
MOTOR_RGBA = (0.25, 0.25, 0.28, 1.0)
METAL_RGBA = (0.72, 0.72, 0.75, 1.0)
#: Contact of the ``collision`` class: torsional and rolling friction, ``solimp``.
TORSIONAL_FRICTION = 0.005
ROLLING_FRICTION = 0.0001
CONTACT_SOLIMP = (0.95, 0.99, 0.001, 0.5, 2.0)


def new_root(model: str, sim: SimParams) -> mjcf.RootElement:
    """Create a robot root with options, sizes and the visual/collision classes.

    Options: implicit-in-velocity integration (``implicitfast``), elliptic friction
    cones with ``impratio`` (no pyramidal creep), and the Newton solver. Constraint
    island discovery is off (``<flag island="disable"/>``, on by default since MuJoCo
    3.3.6): a robot on the floor is one island, its chassis joining every contact, so
    discovery finds the whole constraint set every step and only adds its own cost
    (``python -m wmr_mujoco.bench.island_cost`` measures it; the trajectory is the
    same to the bit, ``tests/models/builders/test_common.py``).
    """
    root = mjcf.RootElement(model=model)
    root.compiler.angle = "radian"
    root.compiler.autolimits = True
    root.option.timestep = sim.timestep
    root.option.integrator = "implicitfast"
    root.option.cone = "elliptic"
    root.option.impratio = sim.impratio
    root.option.flag.island = "disable"
    root.size.nuser_actuator = NUSER_ACTUATOR
    main = root.default
    main.joint.damping = 0
    main.joint.armature = 0
    main.joint.frictionloss = 0
    visual = main.add("default", dclass="visual")
    visual.geom.contype = 0
    visual.geom.conaffinity = 0
    visual.geom.group = 2
    visual.geom.density = 0
    collision = main.add("default", dclass="collision")
    _set_contact(collision.geom, sim)
    return root


def _set_contact(geom: mjcf.Element, sim: SimParams) -> None:
    """Collision group 3, ``condim`` 3, the floor's friction and ``sim``'s softness.

    Contact softness: ``solref`` (time constant, critical damping) and ``solimp``.
    """
    geom.group = 3
    geom.condim = 3
    geom.priority = 1
    geom.friction = (sim.friction, TORSIONAL_FRICTION, ROLLING_FRICTION)
    geom.solref = (sim.contact_timeconst, 1.0)
    geom.solimp = CONTACT_SOLIMP


def contact_pair_kwargs(sim: SimParams) -> dict:
    """Attributes of a ``<pair>`` that contacts exactly as a ``collision``-class geom would.

    MuJoCo fills a pair's unset attributes from the pair defaults (``solref`` 0.02, ...),
    not from its geoms, so every attribute is given. Against a geom of lower priority
    (the scene's floor, priority 0) the collision class's priority 1 makes MuJoCo take
    its ``condim``, friction, ``solref`` and ``solimp`` whole; a contact's five friction
    coefficients are ``(μ, μ, torsional, rolling, rolling)``; ``margin`` and ``gap`` are
    the larger of the two geoms' (both 0).
    """
    mu = sim.friction
    return {"condim": 3,
            "friction": (mu, mu, TORSIONAL_FRICTION, ROLLING_FRICTION, ROLLING_FRICTION),
            "solref": (sim.contact_timeconst, 1.0), "solimp": CONTACT_SOLIMP,
            "margin": 0.0, "gap": 0.0}


#: ``impratio · d`` of a sliding pair's model (:func:`sliding_impratio`): the disc's
#: (``DiscParams``: impratio 1e4 at d = 0.001).
SLIDING_GRIP = 10.0
#: Time constant of a sliding pair's contact in steps (:func:`sliding_pair_kwargs`): above
#: the largest normal-mode gain λ of the roller robots (2.2), the bound of stability.
SLIDING_STEPS = 3


def sliding_impratio(impedance: float) -> float:
    """``impratio`` of a model whose floor pairs have ``impedance`` d: ``SLIDING_GRIP / d``.

    A friction row's regulariser is the normal row's ``(1 − d)/d`` times its diagonal,
    over ``impratio``; gripping friction stays stiff while ``impratio · d · A_t/A_n ≫ 1``
    (``docs/rolling-disc.md`` § 8), so ``impratio`` scales as ``1/d``.

    Raises:
        ValueError: an impedance outside (0, 1].
    """
    if not (0.0 < impedance <= 1.0):
        raise ValueError(f"impedance = {impedance!r}; valid range is (0, 1]")
    return SLIDING_GRIP / impedance


def sliding_pair_kwargs(sim: SimParams, impedance: float, steps: int = SLIDING_STEPS) -> dict:
    """A floor pair's attributes with the disc's remedy for a sliding soft contact.

    A frictional contact in its cone state pushes its geom off the floor by
    ``μ d B_f s`` for slip ``s`` (impedance ``d``, friction reference damping ``B_f``)
    against the weight's ``(1 − d) g`` (``docs/rolling-disc.md`` § 8,
    ``docs/floor-contact.md``). For ``impedance`` > 0 the pair of
    :func:`contact_pair_kwargs` gets

    * ``solimp`` ``d0 = d_width = impedance``: the push ``μ d s / Δt`` stays under ``g``
      for slips up to ``g Δt / (μ d)``;
    * ``solreffriction`` ``B_f = 1/Δt`` in MuJoCo's direct form ``(0, −B_f d)`` (MuJoCo
      divides it by ``d_width``): gripping friction still removes a slip within one step.

    * ``solref`` time constant ``t_c = max(sim.contact_timeconst, steps · Δt)`` (``steps``
      default :data:`SLIDING_STEPS`, at least 2, MuJoCo's own floor). With ``d`` small a
      contact is a spring-damper (MuJoCo scales ``B`` and ``K`` by ``1/d``) whose gain on
      the body is ``λ = eig(A (A + R)⁻¹)/d`` over the normal rows; its damping ``2 λ/t_c``
      is integrated explicitly, so it is stable only while ``λ < t_c/Δt``. MuJoCo's diagonal
      estimate in ``R`` undercounts the coupled inverse inertia of several wheels on one
      body: ``λ`` reaches 1.4 for omni3 and 2.2 for mecanum4 at rest
      (``tests/models/builders/test_common.py`` computes it), above the 2 of the usual ``t_c
      = 2 Δt``.

    * ``solref`` damping ratio ``ζ = sim.floor_dampratio``: MuJoCo's damping
      ``2/(d t_c)`` does not depend on it, its stiffness ``1/(d ζ² t_c²)`` does.

    The weight then rests ``(1 − d) g ζ² t_c²`` deep. ``impedance`` 0 returns
    :func:`contact_pair_kwargs` unchanged.

    Raises:
        ValueError: an impedance that is neither 0 nor in [1e-4, 0.95].
    """
    kwargs = contact_pair_kwargs(sim)
    if impedance == 0.0:
        return kwargs
    if not (1e-4 <= impedance <= CONTACT_SOLIMP[0]):
        raise ValueError(f"impedance = {impedance!r}; valid: 0 (the geoms' contact) or "
                         f"[1e-4, {CONTACT_SOLIMP[0]}]")
    d = float(impedance)
    kwargs["solimp"] = (d, d, *CONTACT_SOLIMP[2:])
    if not (isinstance(steps, int) and steps >= 2):
        raise ValueError(f"steps = {steps!r}; valid: an integer >= 2 (MuJoCo keeps t_c >= 2 Δt)")
    kwargs["solref"] = (max(sim.contact_timeconst, steps * sim.timestep), sim.floor_dampratio)
    kwargs["solreffriction"] = (0.0, -d / sim.timestep)
    return kwargs


def add_roller_default(root: mjcf.RootElement, sim: SimParams, damping: float,
                       armature: float) -> mjcf.Element:
    """The ``roller`` default class of passive rollers on free hinges (omni and mecanum).

    Hinges about the local z axis with the given damping and armature; collision geoms in
    group 3 with ``condim`` 3, the floor friction and contact softness of ``sim``, that
    touch the floor only (``contype`` 0, ``conaffinity`` 1: no two robot geoms collide).
    """
    roller = root.default.add("default", dclass="roller")
    roller.joint.type = "hinge"
    roller.joint.axis = (0, 0, 1)
    roller.joint.damping = damping
    roller.joint.armature = armature
    _set_contact(roller.geom, sim)
    roller.geom.contype = 0
    roller.geom.conaffinity = 1
    return roller


def add_hub(wheel: mjcf.Element, mass: float, radius: float, width: float) -> None:
    """A roller wheel's hub: a uniform cylinder's inertia and visual geoms.

    The inertia is about the axle (local y); the geoms are a cylinder and a mark that
    shows the wheel turning. ``I_y = m r² / 2``, ``I_x = I_z = m (r²/4 + w²/12)``.
    """
    diametral = mass * (radius**2 / 4 + width**2 / 12)
    wheel.add("inertial", pos=(0, 0, 0), mass=mass,
              diaginertia=(diametral, mass * radius**2 / 2, diametral))
    wheel.add("geom", dclass="visual", type="cylinder", size=(radius, width / 2.0),
              zaxis=(0, 1, 0), rgba=WHEEL_RGBA)
    wheel.add("geom", dclass="visual", type="box", size=(0.9 * radius, width / 2 + 0.001,
                                                           0.1 * radius), rgba=MARK_RGBA)


def add_box_body_geoms(body: mjcf.Element, size: Sequence[float],
                       pos: Sequence[float] = (0.0, 0.0, 0.0)) -> None:
    """Add a visual-only box of full edge lengths ``size`` to ``body``."""
    body.add("geom", dclass="visual", type="box", size=[s / 2.0 for s in size],
             pos=list(pos), rgba=BODY_RGBA)


#: Radius of the visual fork blades and axles, as a fraction of the wheel radius (with a
#: floor of 6 mm), and the gap between a wheel face and a blade, m.
FORK_RADIUS_RATIO = 0.06
FORK_MIN_RADIUS = 0.006
FORK_GAP = 0.008


def add_fork(body: mjcf.Element, wheel: WheelParams,
             tops: Sequence[tuple[float, float]], rgba: Sequence[float] = BODY_RGBA,
             centre: tuple[float, float] = (0, 0)) -> None:
    """Visual fork holding a wheel whose axle is parallel to ``body``'s y axis.

    The axle passes through ``centre = (x, z)`` in ``body``'s frame (its origin unless
    given). An axle across the wheel and both blades, and from each blade end a pair of
    blades (one each side of the wheel, clear of its faces) up to each ``(x, z)`` in
    ``tops``, joined there by a crown. Visual class only: no mass, no contact.
    """
    radius = max(FORK_RADIUS_RATIO * wheel.radius, FORK_MIN_RADIUS)
    y = wheel.width / 2.0 + FORK_GAP + radius
    cx, cz = centre
    body.add("geom", dclass="visual", type="capsule", size=(radius,),
             fromto=(cx, -y - radius, cz, cx, y + radius, cz), rgba=rgba)
    for x, z in tops:
        for side in (-1.0, 1.0):
            body.add("geom", dclass="visual", type="capsule", size=(radius,),
                     fromto=(cx, side * y, cz, x, side * y, z), rgba=rgba)
        body.add("geom", dclass="visual", type="capsule", size=(radius,),
                 fromto=(x, -y, z, x, y, z), rgba=rgba)


def add_drive_mount(body: mjcf.Element, motor_from: Sequence[float],
                    motor_to: Sequence[float], axle_to: Sequence[float],
                    motor_radius: float, axle_radius: float) -> None:
    """Visual gear motor and axle holding a driven wheel on ``body`` (the chassis).

    The motor housing is the cylinder from ``motor_from`` to ``motor_to`` (its face
    beside the wheel), the axle the thinner cylinder from ``motor_to`` through the hub to
    ``axle_to``, beyond the wheel's outer face; all three points lie on the wheel's
    axle line. Visual class only: no mass, no contact; fixed to ``body``, so the hub
    turns about the axle.
    """
    body.add("geom", dclass="visual", type="cylinder", size=(motor_radius,),
             fromto=(*motor_from, *motor_to), rgba=MOTOR_RGBA)
    body.add("geom", dclass="visual", type="cylinder", size=(axle_radius,),
             fromto=(*motor_to, *axle_to), rgba=METAL_RGBA)


def add_wheel(parent: mjcf.Element, name: str, wheel: WheelParams,
              pos: Sequence[float], armature: float = 0.0) -> mjcf.Element:
    """Add a thin-disc wheel body spinning on a hinge about its local +y axis.

    The collision geom is an ellipsoid with semi-axes ``(R, w/2, R)``: a thin disc with
    a rounded rim. Against the floor it makes exactly one contact, at its lowest point,
    which for an upright wheel lies directly below the axle at distance R: the
    lecture's point contact of a thin disc, with rolling radius R (less half the
    penetration, a few micrometres). A cylinder would touch at both rim edges and
    scrub in turns, since the two edges would have to roll at different speeds.

    Args:
        parent: body the wheel hangs from.
        name: name of the wheel body and of its hinge.
        wheel: the disc's parameters.
        pos: wheel centre in the parent frame.
        armature: reflected motor inertia on the hinge (driven wheels), kg·m².

    Returns:
        The wheel body; its hinge joint has the same ``name``.

    """
    body = parent.add("body", name=name, pos=list(pos))
    joint = body.add("joint", name=name, type="hinge", axis=(0, 1, 0))
    if armature:
        joint.armature = armature
    add_wheel_geoms(body, name, wheel)
    return body


def add_wheel_geoms(body: mjcf.Element, name: str, wheel: WheelParams) -> None:
    """Give ``body`` a thin disc's inertia, collision cylinder and visual geoms.

    The disc's axle is the body's y axis.
    """
    body.add("inertial", pos=(0, 0, 0), mass=wheel.mass,
             diaginertia=(wheel.diametral_inertia, wheel.axial_inertia,
                          wheel.diametral_inertia))
    half = wheel.width / 2.0
    body.add("geom", name=f"{name}_collision", dclass="collision", type="ellipsoid",
             size=(wheel.radius, half, wheel.radius))
    body.add("geom", dclass="visual", type="cylinder", size=(wheel.radius, half),
             zaxis=(0, 1, 0), rgba=WHEEL_RGBA)
    # A radial stripe on each face makes the spin visible in renders.
    for side in (-1.0, 1.0):
        body.add("geom", dclass="visual", type="box",
                 size=(0.08 * wheel.radius, 0.001, 0.45 * wheel.radius),
                 pos=(0.0, side * (half + 0.001), 0.5 * wheel.radius), rgba=MARK_RGBA)


def add_wheel_actuator(root: mjcf.RootElement, name: str, drive: DriveParams,
                       joint: mjcf.Element | None = None,
                       tendon: mjcf.Element | None = None) -> mjcf.Element:
    """Add a wheel velocity servo ``τ = kv (u − θ̇)`` clamped to the torque limit."""
    target = {"joint": joint} if joint is not None else {"tendon": tendon}
    return root.actuator.add(
        "velocity", name=name, kv=drive.wheel_kv,
        ctrlrange=(-drive.wheel_rate_limit, drive.wheel_rate_limit),
        forcerange=(-drive.wheel_torque_limit, drive.wheel_torque_limit),
        user=(KIND_WHEEL, 0.0, drive.wheel_kv, drive.wheel_rate_limit), **target)


def add_steer_actuator(root: mjcf.RootElement, name: str, joint: mjcf.Element,
                       drive: DriveParams, angle_limit: float) -> mjcf.Element:
    """Add a steering-rate servo (MuJoCo ``intvelocity``).

    The control is the steering rate ω; the actuator state integrates it into a
    target angle φ* (``φ̇* = ω``) and a PD servo tracks it:
    ``τ = kp (φ* − φ) − kv φ̇``. The angle therefore does not drift under load.
    """
    return root.actuator.add(
        "intvelocity", name=name, joint=joint, kp=drive.steer_kp, kv=drive.steer_kv,
        ctrlrange=(-drive.steer_rate_limit, drive.steer_rate_limit),
        actrange=(-angle_limit, angle_limit),
        forcerange=(-drive.steer_torque_limit, drive.steer_torque_limit),
        user=(KIND_STEER, drive.steer_kp, drive.steer_kv, drive.steer_rate_limit))


def add_joint_sensors(root: mjcf.RootElement, wheel_joints: Sequence[str],
                      steer_joints: Sequence[str] = ()) -> None:
    """Add ``jointvel`` sensors for wheels and ``jointpos`` sensors for steering."""
    for j in wheel_joints:
        root.sensor.add("jointvel", name=f"{j}_rate", joint=j)
    for j in steer_joints:
        root.sensor.add("jointpos", name=f"{j}_angle", joint=j)


def add_frame_sensors(root: mjcf.RootElement, site: mjcf.Element) -> None:
    """Add world position, orientation and body-frame velocity sensors at ``site``."""
    root.sensor.add("framepos", name="base_pos", objtype="site", objname=site)
    root.sensor.add("framequat", name="base_quat", objtype="site", objname=site)
    root.sensor.add("velocimeter", name="base_linvel", site=site)
    root.sensor.add("gyro", name="base_angvel", site=site)


def to_xml(root: mjcf.RootElement) -> str:
    """Serialise an mjcf root as clean, Menagerie-style XML.

    dm_control writes the main default class as ``class="/"``, names unnamed elements
    ``//unnamed_*`` and prints 17 digits; this removes the first two and keeps
    :data:`XML_PRECISION` digits, which leaves the compiled model unchanged for the
    builder's parameter values.
    """
    text = root.to_xml_string(pretty_print=False, precision=XML_PRECISION)
    tree = etree.fromstring(text.encode())
    for el in tree.iter():
        if el.get("class") == "/":
            del el.attrib["class"]
        if el.get("name", "").startswith("//unnamed"):
            del el.attrib["name"]
    default = tree.find("default")
    if default is not None:
        inner = default.find("default")
        if inner is not None and inner.get("class") is None:
            for child in list(inner):
                default.append(child)
            default.remove(inner)
        if len(default) == 0:
            tree.remove(default)
    etree.indent(tree, space="  ")
    return etree.tostring(tree, encoding="unicode") + "\n"
