"""A design alternative of omni3's reduced rung: each wheel a sphere on a ball joint.

The lecture's two-degree-of-freedom Swedish wheel (driven spin plus free roll along the
roller axis, one smooth collider) cannot be two serial hinges (the roller hinge turns with
the wheel, or tilts its axle). Here each wheel is a sphere of radius r on a ball joint at
its centre, driven about the chassis-fixed axle by a site transmission with a reference
site on the platform: MuJoCo's ``site`` + ``refsite`` actuator with gear ``(0, 0, 0, 0,
1, 0)`` applies its torque about the reference site's y axis (the axle) and reads the
sphere's angular velocity relative to the platform along it. The roll along the drive
direction's normal is free, and so is the spin about the vertical (no torque reaches it:
``condim`` 3 has no torsional friction). Its price: a ball joint's inertia is one for
every axis, so the motor's reflected inertia (omni3's wheel armature) resists the sideways
roll as much as the spin. Not registered; :mod:`wmr_mujoco.bench.ladder` measures it.
"""

from __future__ import annotations

import math

from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3_reduced import builder

SPHERE_RGBA = (0.55, 0.55, 0.58, 0.6)


def build(params: OmniParams) -> mjcf.RootElement:
    """omni3's platform with three spheres on ball joints, site-driven about the axles."""
    p = params
    r, L = p.wheel_radius, p.wheel_distance
    root = builder.build(p)
    root.model = "omni3_sphere"
    platform = root.worldbody.body["platform"]
    mass, axial, _ = builder.wheel_inertia(p)
    for i in range(3):
        name = f"wheel{i + 1}"
        platform.body[name].remove()
        root.actuator.velocity[name].remove()
        for sensor in list(root.sensor.all_children()):
            joint = getattr(sensor, "joint", None)
            if joint is not None and getattr(joint, "name", joint) == name:
                sensor.remove()
        alpha = 2.0 * math.pi * i / 3.0
        yaw = alpha + math.pi / 2.0
        pos = (L * math.cos(alpha), L * math.sin(alpha), 0.0)
        quat = (math.cos(yaw / 2.0), 0.0, 0.0, math.sin(yaw / 2.0))
        ref = platform.add("site", name=f"{name}_axle", pos=pos, quat=quat)
        wheel = platform.add("body", name=name, pos=pos, quat=quat)
        wheel.add("joint", name=name, type="ball", armature=p.drive.wheel_armature)
        wheel.add("inertial", pos=(0, 0, 0), mass=mass, diaginertia=(axial, axial, axial))
        wheel.add("geom", name=f"{name}_collision", dclass="collision", type="sphere",
                  size=(r,), contype=0, conaffinity=1, mass=0)
        wheel.add("geom", dclass="visual", type="sphere", size=(r,), rgba=SPHERE_RGBA)
        site = wheel.add("site", name=f"{name}_centre")
        d = p.drive
        root.actuator.add("velocity", name=name, site=site, refsite=ref,
                          gear=(0, 0, 0, 0, 1, 0), kv=d.wheel_kv,
                          ctrlrange=(-d.wheel_rate_limit, d.wheel_rate_limit),
                          forcerange=(-d.wheel_torque_limit, d.wheel_torque_limit),
                          user=(common.KIND_WHEEL, 0.0, d.wheel_kv, d.wheel_rate_limit))
    return root


def no_pairs(scene: mjcf.RootElement, params: OmniParams) -> None:
    """The spheres touch the floor through their contact bits: no scene pairs."""
