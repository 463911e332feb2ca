"""Parts shared by the builders of the two steered classes.

(2,1) one steered wheel (``robots/single_steer/builder.py``), (1,2) two steered wheels
(``robots/double_steer/builder.py``). Both are made of existing parts: the thin-disc wheel
of :mod:`~wmr_mujoco.models.builders.common` on a steering fork (a vertical hinge through
the wheel centre: a *centred* steerable wheel) and the ball caster of
:mod:`~wmr_mujoco.models.builders.caster`.
"""

from __future__ import annotations

from collections.abc import Sequence

from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.models.params import DriveParams, WheelParams
from wmr_mujoco.models.solids import FORK_BOX, fork_yaw_inertia  # noqa: F401  (re-exported)

CHASSIS_COM_HEIGHT = 0.04
FORK_HEIGHT = FORK_BOX[2]
#: Height of the visual fork crown above the wheel's top, m.
FORK_CROWN_GAP = 0.02


def add_steered_wheel(root: mjcf.RootElement, chassis: mjcf.Element, prefix: str,
                      wheel: WheelParams, fork_mass: float, drive: DriveParams,
                      pos: Sequence[float]) -> None:
    """A fork on a vertical steering hinge ``{prefix}_steer`` carrying a driven wheel.

    The steering axis passes through the wheel centre (a centred steerable wheel). Adds
    the wheel-rate servo ``{prefix}_wheel`` and the steering-rate servo
    ``{prefix}_steer``.
    """
    fork = chassis.add("body", name=f"{prefix}_fork", pos=list(pos))
    limit = drive.steer_angle_limit
    steer = fork.add("joint", name=f"{prefix}_steer", type="hinge", axis=(0, 0, 1),
                     range=(-limit, limit))
    fork.add("inertial", pos=(0, 0, FORK_HEIGHT / 2.0), mass=fork_mass,
             diaginertia=common.box_inertia(fork_mass, FORK_BOX))
    fork.add("geom", dclass="visual", type="capsule", fromto=(0, 0, 0, 0, 0, FORK_HEIGHT),
             size=(0.01,), rgba=common.BODY_RGBA)
    # Blades either side of the wheel up to a crown on the steering column.
    common.add_fork(fork, wheel, tops=((0.0, wheel.radius + FORK_CROWN_GAP),))
    name = f"{prefix}_wheel"
    common.add_wheel(fork, name, wheel, pos=(0, 0, 0), armature=drive.wheel_armature)
    common.add_wheel_actuator(root, name, drive, joint=name)
    common.add_steer_actuator(root, f"{prefix}_steer", steer, drive, limit)


def add_chassis(root: mjcf.RootElement, height: float, mass: float, com: Sequence[float],
             size: Sequence[float], visual_x: tuple[float, float]
             ) -> tuple[mjcf.Element, mjcf.Element]:
    """Chassis on a free joint; inertia of the full plate ``size`` about ``com``.

    The visual plate spans only ``visual_x`` along x, so that the wheels stay visible.
    """
    chassis = root.worldbody.add("body", name="chassis", pos=(0, 0, height))
    chassis.add("freejoint", name="chassis")
    chassis.add("inertial", pos=list(com), mass=mass, diaginertia=common.box_inertia(mass, size))
    x0, x1 = visual_x
    common.add_box_body_geoms(chassis, (x1 - x0, size[1], size[2]),
                              pos=(0.5 * (x0 + x1), com[1], com[2]))
    site = chassis.add("site", name="base", pos=(0, 0, 0))
    return chassis, site
