"""Builder of the double-steer robot, class (1,2)."""

from __future__ import annotations

from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.models.builders.caster import add_ball_caster
from wmr_mujoco.robots.double_steer.params import DOUBLE_STEER, DoubleSteerParams
from wmr_mujoco.robots.steered.builder import (
    CHASSIS_COM_HEIGHT,
    FORK_HEIGHT,
    add_chassis,
    add_steered_wheel,
)


def build(params: DoubleSteerParams = DOUBLE_STEER) -> mjcf.RootElement:
    """Class (1,2): two centred steerable driven wheels on the x axis and a ball caster.

    Kinematic tree::

        world ─ chassis [free joint; origin midway between the steering axes]
                 ├─ front_fork [hinge front_steer about z]  (x = +a)
                 │    └─ front_wheel [hinge about y, driven]
                 ├─ rear_fork  [hinge rear_steer about z]   (x = −a)
                 │    └─ rear_wheel [hinge about y, driven]
                 └─ caster [ball joint]  (0, caster_y)
    """
    p = params
    r, rc, a = p.wheel.radius, p.caster.radius, p.half_wheelbase
    root = common.new_root("double_steer", p.sim)
    chassis, site = add_chassis(root, r, p.chassis_mass, (0, p.chassis_com_y, CHASSIS_COM_HEIGHT),
                             p.chassis_size, (-a + r + 0.015, a - r - 0.015))
    chassis.add("geom", dclass="visual", type="capsule", size=(0.01,),
                fromto=(-a, 0, FORK_HEIGHT, a, 0, FORK_HEIGHT), rgba=common.BODY_RGBA)
    for prefix, x in (("front", a), ("rear", -a)):
        add_steered_wheel(root, chassis, prefix, p.wheel, p.fork_mass, p.drive, (x, 0, 0))
    add_ball_caster(chassis, "caster", p.caster, pos=(0, p.caster_y, rc - r),
                    mount_z=CHASSIS_COM_HEIGHT - p.chassis_size[2] / 2.0)
    common.add_joint_sensors(root, ["front_wheel", "rear_wheel"], ["front_steer", "rear_steer"])
    common.add_frame_sensors(root, site)
    return root
