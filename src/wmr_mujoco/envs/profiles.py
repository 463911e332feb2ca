"""Per-robot settings of the learning environments: one table, no branches on names.

A robot is offered as an environment when its registry entry can be driven
(``RobotSpec.command``, :mod:`wmr_mujoco.drive`); this table adds what the tasks need to
know about its size and agility, and its randomisation bands. A drivable robot missing
from the table gets :data:`DEFAULT`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace

from wmr_mujoco import drive
from wmr_mujoco.envs.randomization import Bands
from wmr_mujoco.robots import get_spec


@dataclass(frozen=True)
class Profile:
    """How the tasks are scaled to one robot.

    Attributes:
        stem: the robot's part of the environment id (``wmr/<stem>-<Task>-v0``).
        tasks: the tasks offered.
        scale: task length scale L, m (goal distances, path length and tolerances).
        max_curvature: sharpest turn of a random path, 1/m (within the robot's reach).
        control_period: seconds per environment step.
        bands: domain randomisation bands (:class:`~wmr_mujoco.envs.randomization.Bands`).
        task_options: per task, defaults of its options that differ for this robot.
    """

    stem: str
    tasks: tuple[str, ...] = ("GoToGoal", "FollowPath")
    scale: float = 1.0
    max_curvature: float = 1.0
    control_period: float = 0.02
    bands: Bands = Bands()
    task_options: Mapping[str, Mapping[str, float]] = field(default_factory=dict)


#: Wheels whose rolling radius is set by passive rollers, not one geom: not randomised.
ROLLER_BANDS = Bands(wheel_radius=None)

PROFILES: dict[str, Profile] = {
    "diffdrive": Profile("DiffDrive", scale=1.0, max_curvature=1.5),
    "omni3": Profile("Omni3", scale=0.5, max_curvature=3.0, bands=ROLLER_BANDS),
    # omni3's size; its wheels touch the floor through one low-friction capsule each.
    "omni3_reduced": Profile("Omni3Reduced", scale=0.5, max_curvature=3.0,
                             bands=ROLLER_BANDS),
    "mecanum4": Profile("Mecanum4", scale=1.0, max_curvature=1.5, bands=ROLLER_BANDS),
    # Planar model: its joints hold the frame level (no pitch), so wheels of different
    # radii would lift one of them off the floor (test_randomization checks the others).
    "bicycle": Profile("Bicycle", scale=3.0, max_curvature=0.5,
                       bands=Bands(wheel_radius=None)),
    "tricycle": Profile("Tricycle", scale=1.0, max_curvature=1.0),
    # Its yaw is free (a Chaplygin sleigh: the steered wheel's one constraint fixes
    # neither heading nor yaw rate), so its goal is a position: any heading counts.
    "single_steer": Profile("SingleSteer", scale=1.0, max_curvature=1.0,
                            task_options={"GoToGoal": {"heading_tolerance": 4.0}}),
    "double_steer": Profile("DoubleSteer", scale=1.0, max_curvature=1.0),
    "disc": Profile("Disc", scale=1.0, max_curvature=1.0),
    # Knife-edge wheels (no radius band); a balance task at 100 Hz.
    "whipple": Profile("Whipple", tasks=("StayUpright",), control_period=0.01,
                       bands=Bands(friction=(0.7, 1.3), mass=(0.9, 1.1), wheel_radius=None,
                                   servo_gain=(0.9, 1.1))),
}

#: A robot not in the table: unit scale, and no wheel-radius band (its wheels may roll on
#: rollers or other bodies, whose radius is not one geom's).
DEFAULT = Profile("", bands=Bands(wheel_radius=None))


def drivable() -> list[str]:
    """Registered robots that the stepping API can drive (they have actuators)."""
    return drive.drivable()


def robot_name(robot: str) -> str:
    """The registry name of a drivable robot (typed loosely, as ``get_spec`` takes it).

    Raises:
        ValueError: unknown robot, or one without actuators; the message lists valid ones.
    """
    name = get_spec(robot).name
    if name not in drivable():
        raise ValueError(f"robot {name!r} has no natural command (no actuators); robots "
                         f"with environments: {', '.join(drivable())}")
    return name


def profile(robot: str) -> Profile:
    """The robot's profile (the default one, with a stem from its name, if not listed).

    Raises:
        ValueError: unknown robot, or one without actuators; the message lists valid ones.
    """
    name = robot_name(robot)
    if name in PROFILES:
        return PROFILES[name]
    return replace(DEFAULT, stem="".join(w.title() for w in name.split("_")))
