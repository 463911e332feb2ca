"""Builder of the single-steer robot, class (2,1)."""

from __future__ import annotations

from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.models.builders.caster import add_ball_caster
from wmr_mujoco.robots.single_steer.params import SINGLE_STEER, SingleSteerParams
from wmr_mujoco.robots.steered.builder import (
    CHASSIS_COM_HEIGHT,
    FORK_HEIGHT,
    add_chassis,
    add_steered_wheel,
)


def build(params: SingleSteerParams = SINGLE_STEER) -> mjcf.RootElement:
    """Class (2,1): one centred steerable driven wheel, two ball casters ahead of it.

    Kinematic tree::

        world ─ chassis [free joint; origin on the steering axis, wheel-centre height]
                 ├─ drive_fork [hinge drive_steer about z]
                 │    └─ drive_wheel [hinge about y, driven]
                 ├─ caster_left  [ball joint]  (caster_x, +caster_y)
                 └─ caster_right [ball joint]  (caster_x, −caster_y)
    """
    p = params
    r, rc = p.wheel.radius, p.caster.radius
    root = common.new_root("single_steer", p.sim)
    chassis, site = add_chassis(root, r, p.chassis_mass, (p.chassis_com_x, 0, CHASSIS_COM_HEIGHT),
                             p.chassis_size, (r + 0.015, p.caster_x + 0.05))
    chassis.add("geom", dclass="visual", type="capsule", size=(0.01,),
                fromto=(0, 0, FORK_HEIGHT, r + 0.015, 0, CHASSIS_COM_HEIGHT),
                rgba=common.BODY_RGBA)
    add_steered_wheel(root, chassis, "drive", p.wheel, p.fork_mass, p.drive, (0, 0, 0))
    for side, y in (("left", 1.0), ("right", -1.0)):
        add_ball_caster(chassis, f"caster_{side}", p.caster,
                        pos=(p.caster_x, y * p.caster_y, rc - r),
                        mount_z=CHASSIS_COM_HEIGHT - p.chassis_size[2] / 2.0)
    common.add_joint_sensors(root, ["drive_wheel"], ["drive_steer"])
    common.add_frame_sensors(root, site)
    return root
