"""Per-robot settings of the learning environments, read from each robot's registry entry.

A robot is offered as an environment when its registry entry can be driven
(``RobotSpec.command``, :mod:`wmr_mujoco.drive`); its entry's ``learning`` field
(:class:`~wmr_mujoco.robots.learning.Learning`, filled in ``robots/<robot>/__init__.py``)
says how the tasks are scaled to its size and agility, and its randomisation bands. A
drivable robot whose entry has none gets :data:`~wmr_mujoco.robots.learning.DEFAULT`.
"""

from __future__ import annotations

from dataclasses import replace

from wmr_mujoco import drive
from wmr_mujoco.robots import get_spec
from wmr_mujoco.robots.learning import DEFAULT, Learning

#: The settings' type (its historical name here).
Profile = Learning

__all__ = ["Profile", "drivable", "profile", "robot_name"]


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


def profile(robot: str) -> Learning:
    """The robot's settings (its entry's ``learning``, else the default), with its stem.

    An empty stem is made from the registry name (``single_steer`` -> ``SingleSteer``).

    Raises:
        ValueError: unknown robot, or one without actuators; the message lists valid ones.
    """
    spec = get_spec(robot_name(robot))
    found = getattr(spec, "learning", None) or DEFAULT  # a foreign entry may lack the field
    if found.stem:
        return found
    return replace(found, stem="".join(w.title() for w in spec.name.split("_")))
