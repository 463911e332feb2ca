"""What a robot's learning environments need to know about it (:class:`Learning`).

A robot's registry entry (``RobotSpec.learning``, ``robots/<robot>/__init__.py``) carries
how the tasks of :mod:`wmr_mujoco.envs` and :mod:`wmr_mujoco.suite` are scaled to it, and
its domain-randomisation bands (:class:`Bands`), so that the application layer reads them
from the entry and never branches on a robot's name. A drivable robot without an entry
gets :data:`DEFAULT` (its id stem made from its name).

Every band is a range of factors on a nominal quantity; :data:`PHYSICAL` bounds them
(a coefficient of friction of rubber on a floor between about 0.1 and 3 times the
nominal 1.0; masses within a factor of 2; wheel radii within ±10 %, worn or
over-inflated tyres; servo gains within a factor of 5): beyond them the model leaves
what it describes. :mod:`wmr_mujoco.envs.randomization` applies them.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from types import MappingProxyType

Band = tuple[float, float]

#: The physical range of each factor (module docstring).
PHYSICAL: Mapping[str, Band] = MappingProxyType({
    "friction": (0.1, 3.0), "mass": (0.5, 2.0), "wheel_radius": (0.9, 1.1),
    "servo_gain": (0.2, 5.0)})


@dataclass(frozen=True)
class Bands:
    """Factor bands of one robot (None: that quantity is not randomised).

    Raises:
        ValueError: a band that is not ``lo <= hi`` inside its :data:`PHYSICAL` range.
    """

    friction: Band | None = (0.7, 1.3)
    mass: Band | None = (0.85, 1.15)
    wheel_radius: Band | None = (0.98, 1.02)
    servo_gain: Band | None = (0.8, 1.2)

    def __post_init__(self) -> None:
        for f in fields(self):
            band = getattr(self, f.name)
            if band is None:
                continue
            lo, hi = PHYSICAL[f.name]
            ok = (isinstance(band, (tuple, list)) and len(band) == 2
                  and all(isinstance(b, (int, float)) and math.isfinite(b) for b in band))
            if not (ok and lo <= band[0] <= band[1] <= hi):
                raise ValueError(f"randomisation band {f.name}={band!r}: need (lo, hi) with "
                                 f"{lo} <= lo <= hi <= {hi} (the physical range of the "
                                 f"{f.name} factor)")

    def replace(self, **changes: Band | None) -> Bands:
        """A copy with some bands changed (checked like the constructor)."""
        unknown = sorted(set(changes) - {f.name for f in fields(self)})
        if unknown:
            raise ValueError(f"unknown randomisation band(s) {unknown}; valid: "
                             f"{', '.join(f.name for f in fields(self))}")
        return Bands(**{**{f.name: getattr(self, f.name) for f in fields(self)}, **changes})


#: Wheels whose rolling radius is set by passive rollers or knife edges, not one geom's
#: size: every band but the wheel radius.
NO_RADIUS_BANDS = Bands(wheel_radius=None)


@dataclass(frozen=True)
class Learning:
    """How the learning tasks are scaled to one robot.

    Attributes:
        stem: the robot's part of the environment id (``wmr/<stem>-<Task>-v0``; empty:
            made from the registry name, ``single_steer`` -> ``SingleSteer``).
        tasks: the tasks offered.
        scale: task length scale L, m (goal distances, path length and tolerances).
        max_curvature: sharpest turn of a random path, 1/m (within the robot's reach).
        control_period: seconds per environment step.
        bands: domain randomisation bands.
        task_options: per task, defaults of its options that differ for this robot.
        steer_arm: the field of the robot's parameters that is the distance ``ℓ`` from the
            point that follows a path to a steered axle, for the scripted controllers'
            steering law ``δ = atan(ℓ κ)`` (:mod:`wmr_mujoco.envs.scripted`): the wheelbase
            of a car-like ``(v, steer)`` command, the half wheelbase of a
            ``(v, front_steer, rear_steer)`` one; empty: no such arm (a ``(v, steer)``
            command then steers one wheel at the centre).
    """

    stem: str = ""
    tasks: tuple[str, ...] = ("GoToGoal", "FollowPath")
    scale: float = 1.0
    max_curvature: float = 1.0
    control_period: float = 0.02
    bands: Bands = Bands()
    task_options: Mapping[str, Mapping[str, float]] = field(default_factory=dict)
    steer_arm: str = ""

    def __post_init__(self) -> None:
        if not isinstance(self.steer_arm, str) or (self.steer_arm and
                                                   not self.steer_arm.isidentifier()):
            raise ValueError(f"Learning.steer_arm={self.steer_arm!r}: must be the name of a "
                             "field of the robot's parameters, or empty")
        for name in ("scale", "max_curvature", "control_period"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not (
                    math.isfinite(value) and value > 0):
                raise ValueError(f"Learning.{name}={value!r}: must be a positive finite "
                                 "number")
        if not self.tasks:
            raise ValueError("Learning.tasks is empty: a robot offers at least one task")


#: A robot whose entry has none: unit scale, and no wheel-radius band (its wheels may
#: roll on rollers or other bodies, whose radius is not one geom's).
DEFAULT = Learning(bands=NO_RADIUS_BANDS)
