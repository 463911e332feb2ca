"""Builder of the planar bicycle (lecture section 2)."""

from __future__ import annotations

from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.robots.bicycle.params import BicycleParams

#: Frame modelled as a box of these edge lengths (for its inertia), with its CoM at
#: mid-wheelbase, ``FRAME_COM_HEIGHT`` above the rear axle.
FRAME_HEIGHT = 0.5
FRAME_WIDTH = 0.1
FRAME_COM_HEIGHT = 0.3
#: Fork modelled as a vertical box of this height (for its inertia).
FORK_HEIGHT = 0.4


def build(params: BicycleParams) -> mjcf.RootElement:
    """Planar bicycle held upright by its joints.

    Kinematic tree::

        world ─ frame [slides x, y, z; hinge yaw about z, through the rear axle]
                 ├─ rear_wheel [hinge about y, driven]
                 └─ fork [hinge steer about z, through the front axle]
                      └─ front_wheel [hinge about y, free]

    The frame has no roll and no pitch degree of freedom: that is how the lecture's
    planar (non-balancing) bicycle is kept upright. The z slide is free, so the weight
    rests on the two wheels and drive, steering and side forces all pass through the
    wheel-floor contacts. ``(x, y)`` of the frame is the rear contact point and the
    yaw hinge angle is the heading ψ (lecture coordinates ``(x, y, ψ, φ)``).
    """
    p = params
    rr, rf, wb = p.rear_wheel.radius, p.front_wheel.radius, p.wheelbase
    root = common.new_root("bicycle", p.sim)
    frame = root.worldbody.add("body", name="frame", pos=(0, 0, rr))
    for axis_name, axis in (("x", (1, 0, 0)), ("y", (0, 1, 0)), ("z", (0, 0, 1))):
        frame.add("joint", name=f"frame_{axis_name}", type="slide", axis=axis)
    frame.add("joint", name="yaw", type="hinge", axis=(0, 0, 1))
    frame.add("inertial", pos=(wb / 2.0, 0, FRAME_COM_HEIGHT), mass=p.frame_mass,
              diaginertia=common.box_inertia(p.frame_mass,
                                             (wb, FRAME_WIDTH, FRAME_HEIGHT)))
    common.add_box_body_geoms(frame, (wb, 0.04, 0.04), pos=(wb / 2.0, 0, 0.45))
    common.add_box_body_geoms(frame, (0.04, 0.04, 0.45), pos=(0.25 * wb, 0, 0.25))
    # Seat stays and chain stays: the rear wheel held on both sides, in its frame.
    common.add_fork(frame, p.rear_wheel, tops=((0.25 * wb, 0.45), (0.25 * wb, 0.03)))
    site = frame.add("site", name="base", pos=(0, 0, 0))
    common.add_wheel(frame, "rear_wheel", p.rear_wheel, pos=(0, 0, 0),
                     armature=p.drive.wheel_armature)
    fork = frame.add("body", name="fork", pos=(wb, 0, rf - rr))
    steer = fork.add("joint", name="steer", type="hinge", axis=(0, 0, 1),
                     range=(-p.drive.steer_angle_limit, p.drive.steer_angle_limit))
    fork.add("inertial", pos=(0, 0, FORK_HEIGHT / 2.0), mass=p.fork_mass,
             diaginertia=common.box_inertia(p.fork_mass, (0.05, 0.1, FORK_HEIGHT)))
    # Blades either side of the front wheel up to the crown, then the steerer tube.
    common.add_fork(fork, p.front_wheel, tops=((0.0, rf + 0.05),))
    fork.add("geom", dclass="visual", type="capsule", fromto=(0, 0, rf + 0.05, 0, 0, 0.5),
             size=(0.015,), rgba=common.BODY_RGBA)
    fork.add("geom", dclass="visual", type="capsule", fromto=(0, -0.25, 0.5, 0, 0.25, 0.5),
             size=(0.012,), rgba=common.BODY_RGBA)
    common.add_wheel(fork, "front_wheel", p.front_wheel, pos=(0, 0, 0))
    common.add_wheel_actuator(root, "rear_wheel", p.drive, joint="rear_wheel")
    common.add_steer_actuator(root, "steer", steer, p.drive, p.drive.steer_angle_limit)
    common.add_joint_sensors(root, ["rear_wheel", "front_wheel"], ["steer"])
    common.add_frame_sensors(root, site)
    return root
