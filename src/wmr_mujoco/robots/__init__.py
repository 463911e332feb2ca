"""The registry of robots: one folder per robot, one line per robot below.

Each robot folder (``robots/<name>/``) holds its parameters (``params.py``), its builder
(``builder.py``), its own analytic model where no other robot uses it, and in its
``__init__.py`` ``SPEC``, a :class:`RobotSpec` holding its parameters type, builder, model
files, analytic adapters per scenario kind, judges, probes, targets and scenarios. Robots
of one family share a family folder (``roller_wheels/``, ``steered/``). Generic code
(validation, report, rendering, benchmarks, command line) reads robots only from
:data:`ROBOTS`, never by name, and nothing below this package imports it. Adding a robot
is its own folder and one line in :data:`ROBOTS`; :func:`registered` adds one for a while
(tests, a foreign model).
Every entry gets the closed-loop scenario families that fit its command map
(:func:`~wmr_mujoco.loop.tasks.families.with_loop_scenarios`).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

from wmr_mujoco.choices import match_name
from wmr_mujoco.loop.tasks.families import with_loop_scenarios
from wmr_mujoco.robots import (
    bicycle,
    diffdrive,
    disc,
    disc_free,
    double_steer,
    mecanum4,
    omni3,
    omni3_reduced,
    single_steer,
    tricycle,
    whipple,
)
from wmr_mujoco.robots.spec import Clip, Picture, RobotSpec

__all__ = ["ROBOTS", "Clip", "Picture", "RobotSpec", "get_spec", "register", "registered",
           "unregister"]

ROBOTS: dict[str, RobotSpec] = {spec.name: with_loop_scenarios(spec) for spec in (
    disc.SPEC,
    disc_free.SPEC,
    bicycle.SPEC,
    tricycle.SPEC,
    omni3.SPEC,
    omni3_reduced.SPEC,
    mecanum4.SPEC,
    diffdrive.SPEC,
    single_steer.SPEC,
    double_steer.SPEC,
    whipple.SPEC,
)}


def get_spec(robot: str) -> RobotSpec:
    """Look a robot up by name, typed loosely (:func:`~wmr_mujoco.choices.match_name`).

    Any case, or a unique prefix: ``"OMNI3"`` and ``"mec"`` are robots.

    Raises:
        ValueError: the name matches no robot (the message suggests the nearest and lists
            the valid names) or several.
    """
    if isinstance(robot, str) and robot in ROBOTS:
        return ROBOTS[robot]
    return ROBOTS[match_name(robot, list(ROBOTS), "robot")]


def register(spec: RobotSpec) -> None:
    """Add a robot to the registry.

    Raises:
        ValueError: the name is taken.
    """
    if spec.name in ROBOTS:
        raise ValueError(f"robot {spec.name!r} is already registered")
    ROBOTS[spec.name] = spec


def unregister(name: str) -> None:
    """Remove a robot from the registry (a no-op for an unknown name)."""
    ROBOTS.pop(name, None)


@contextmanager
def registered(spec: RobotSpec) -> Iterator[RobotSpec]:
    """Register ``spec`` for the duration of a ``with`` block."""
    register(spec)
    try:
        yield spec
    finally:
        unregister(spec.name)
