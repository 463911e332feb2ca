"""Builder of the differential-drive robot on a ball caster (Campion class (2,0))."""

from __future__ import annotations

from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.models.builders.caster import add_ball_caster
from wmr_mujoco.robots.diffdrive.params import DIFFDRIVE, DiffDriveParams

#: Plate CoM height above the axle.
CHASSIS_COM_HEIGHT = 0.04
#: Visual drive of each wheel (fractions of the wheel radius r): gear-motor radius and
#: length, axle radius; thickness of the bracket holding the motor under the plate, m.
MOTOR_RADIUS = 0.3
MOTOR_LENGTH = 0.9
AXLE_RADIUS = 0.12
BRACKET_THICKNESS = 0.006


def _add_drive_visuals(chassis: mjcf.Element, params: DiffDriveParams, side: float,
                       underside: float) -> None:
    """Bracket under the plate, its gear motor and the axle through the hub on ``side``.

    ``side`` is +1 (left) or −1 (right); ``underside`` the plate's underside height.
    """
    p = params
    r = p.wheel.radius
    motor_out = p.track / 2.0 - p.wheel.width / 2.0 - 0.003
    motor_in = motor_out - MOTOR_LENGTH * r
    axle_end = p.track / 2.0 + p.wheel.width / 2.0 + 0.008
    common.add_drive_mount(chassis, (0.0, side * motor_in, 0.0), (0.0, side * motor_out, 0.0),
                           (0.0, side * axle_end, 0.0), MOTOR_RADIUS * r, AXLE_RADIUS * r)
    top = underside + 0.001  # into the plate, so no gap shows
    bottom = -MOTOR_RADIUS * r
    chassis.add("geom", dclass="visual", type="box",
                size=(1.2 * MOTOR_RADIUS * r, BRACKET_THICKNESS / 2.0, (top - bottom) / 2.0),
                pos=(0.0, side * (motor_in + BRACKET_THICKNESS), (top + bottom) / 2.0),
                rgba=common.METAL_RGBA)


def build(params: DiffDriveParams = DIFFDRIVE) -> mjcf.RootElement:
    """Differential drive on a free joint resting on two wheels and a ball caster.

    Kinematic tree::

        world ─ chassis [free joint; origin at the axle midpoint, wheel-centre height]
                 ├─ left_wheel  [hinge about y, driven]  (y = +b/2)
                 ├─ right_wheel [hinge about y, driven]  (y = −b/2)
                 └─ caster      [ball joint]  (x = caster_x, centre r_c above the floor)

    Actuators ``left_wheel`` and ``right_wheel``: wheel-rate servos (torque mode through
    :func:`wmr_mujoco.actuation.set_actuation_mode`).
    """
    p = params
    r, rc = p.wheel.radius, p.caster.radius
    root = common.new_root("diffdrive", p.sim)
    chassis = root.worldbody.add("body", name="chassis", pos=(0, 0, r))
    chassis.add("freejoint", name="chassis")
    chassis.add("inertial", pos=(p.chassis_com_x, 0, CHASSIS_COM_HEIGHT), mass=p.chassis_mass,
                diaginertia=common.box_inertia(p.chassis_mass, p.chassis_size))
    common.add_box_body_geoms(chassis, p.chassis_size,
                              pos=(p.chassis_com_x, 0, CHASSIS_COM_HEIGHT))
    underside = CHASSIS_COM_HEIGHT - p.chassis_size[2] / 2.0
    site = chassis.add("site", name="base", pos=(0, 0, 0))
    joints = []
    for side, y in (("left", 1.0), ("right", -1.0)):
        name = f"{side}_wheel"
        _add_drive_visuals(chassis, p, y, underside)
        common.add_wheel(chassis, name, p.wheel, pos=(0, y * p.track / 2.0, 0),
                         armature=p.drive.wheel_armature)
        common.add_wheel_actuator(root, name, p.drive, joint=name)
        joints.append(name)
    add_ball_caster(chassis, "caster", p.caster, pos=(p.caster_x, 0, rc - r),
                    mount_z=underside)
    common.add_joint_sensors(root, joints)
    common.add_frame_sensors(root, site)
    return root
