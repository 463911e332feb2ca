"""Builder of the tricycle (lecture section 3)."""

from __future__ import annotations

from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.robots.tricycle.params import TricycleParams

#: Chassis modelled as a plate of this thickness (for its inertia); its CoM lies
#: ``CHASSIS_COM_HEIGHT`` above the rear axle.
CHASSIS_THICKNESS = 0.05
CHASSIS_COM_HEIGHT = 0.05
FORK_HEIGHT = 0.15


def build(params: TricycleParams) -> mjcf.RootElement:
    """Tricycle on a free joint resting on its three wheels.

    Kinematic tree::

        world ─ chassis [free joint; origin at the rear-axle midpoint]
                 ├─ rear_left_wheel  [hinge about y]  (y = +w/2)
                 ├─ rear_right_wheel [hinge about y]  (y = −w/2)
                 └─ fork [hinge steer about z, through the front axle at x = ℓ]
                      └─ front_wheel [hinge about y, free]

    ``rear_drive="left"``: actuator ``rear_left_wheel`` drives the left wheel and the
    right wheel spins freely. ``rear_drive="differential"``: actuator ``rear_drive``
    acts on the fixed tendon ``(θ_L + θ_R)/2``, i.e. an open differential that splits
    its torque equally and leaves ``θ_L − θ_R`` free.
    """
    p = params
    rr, rf, wb, tr = p.rear_wheel.radius, p.front_wheel.radius, p.wheelbase, p.track
    root = common.new_root("tricycle", p.sim)
    chassis = root.worldbody.add("body", name="chassis", pos=(0, 0, rr))
    chassis.add("freejoint", name="chassis")
    plate = (wb, tr - p.rear_wheel.width - 0.02, CHASSIS_THICKNESS)
    chassis.add("inertial", pos=(p.chassis_com_x * wb, 0, CHASSIS_COM_HEIGHT),
                mass=p.chassis_mass, diaginertia=common.box_inertia(p.chassis_mass, plate))
    # The visual plate stops short of the fork so that the front wheel stays visible.
    common.add_box_body_geoms(chassis, (0.7 * wb, plate[1], plate[2]),
                              pos=(0.35 * wb, 0, CHASSIS_COM_HEIGHT))
    chassis.add("geom", dclass="visual", type="capsule", size=(0.012,),
                fromto=(0, -tr / 2.0, 0, 0, tr / 2.0, 0), rgba=common.BODY_RGBA)
    site = chassis.add("site", name="base", pos=(0, 0, 0))
    common.add_wheel(chassis, "rear_left_wheel", p.rear_wheel, pos=(0, tr / 2.0, 0),
                     armature=p.drive.wheel_armature)
    common.add_wheel(chassis, "rear_right_wheel", p.rear_wheel, pos=(0, -tr / 2.0, 0),
                     armature=p.drive.wheel_armature if p.rear_drive == "differential" else 0.0)
    fork = chassis.add("body", name="fork", pos=(wb, 0, rf - rr))
    steer = fork.add("joint", name="steer", type="hinge", axis=(0, 0, 1),
                     range=(-p.drive.steer_angle_limit, p.drive.steer_angle_limit))
    fork.add("inertial", pos=(0, 0, FORK_HEIGHT / 2.0), mass=p.fork_mass,
             diaginertia=common.box_inertia(p.fork_mass, (0.04, 0.06, FORK_HEIGHT)))
    # Blades either side of the front wheel up to the crown, then the steerer tube.
    crown = rf + 0.03
    common.add_fork(fork, p.front_wheel, tops=((0.0, crown),))
    fork.add("geom", dclass="visual", type="capsule", fromto=(0, 0, crown, 0, 0, FORK_HEIGHT),
             size=(0.012,), rgba=common.BODY_RGBA)
    common.add_wheel(fork, "front_wheel", p.front_wheel, pos=(0, 0, 0))
    if p.rear_drive == "differential":
        tendon = root.tendon.add("fixed", name="differential")
        tendon.add("joint", joint="rear_left_wheel", coef=0.5)
        tendon.add("joint", joint="rear_right_wheel", coef=0.5)
        common.add_wheel_actuator(root, "rear_drive", p.drive, tendon=tendon)
    else:
        common.add_wheel_actuator(root, "rear_left_wheel", p.drive, joint="rear_left_wheel")
    common.add_steer_actuator(root, "steer", steer, p.drive, p.drive.steer_angle_limit)
    common.add_joint_sensors(root, ["rear_left_wheel", "rear_right_wheel", "front_wheel"],
                             ["steer"])
    common.add_frame_sensors(root, site)
    return root
