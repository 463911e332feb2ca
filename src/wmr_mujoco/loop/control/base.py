"""What every controller shares: the state it reads, the references, the command kinds.

A controller maps ``(state, reference, t) -> command`` in the robot's natural command
space (``DRIVE_CONTRACT``): it reads ``state.pose = (x, y, ψ)``, ``state.twist =
(u, v, r)`` and ``state.extra`` (robot-specific: the Whipple bicycle's lean and steer).
The command spaces (:class:`CommandKind`):

* ``UNICYCLE``: ``(v, ω)``, forward speed m/s and yaw rate rad/s;
* ``CAR``: ``(v, δ)``, rear-axle speed m/s and steering angle rad (wheelbase ℓ:
  ``ψ̇ = v tan δ / ℓ``);
* ``HOLONOMIC``: body twist ``(u, v, r)``, m/s, m/s, rad/s;
* ``WHIPPLE``: ``(rear-wheel speed m/s, steer torque N·m)``.

A path follower computes a path curvature ``κ`` (pure pursuit) or a steering angle
(Stanley) and :func:`steer_command` writes it in either planar space: a unicycle with
a virtual wheelbase ℓ turns exactly like the car (``ω = v tan δ / ℓ = v κ``).

References: a goal pose ``(x, y, ψ)``, a :class:`~wmr_mujoco.loop.control.paths.Path`, or a
:class:`Trajectory` (a path travelled at constant speed: a pose for every time).
"""

from __future__ import annotations

import enum
import math
from abc import ABC, abstractmethod
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, ClassVar, Protocol

import numpy as np

from wmr_mujoco.analytic.planar import wrap_angle
from wmr_mujoco.loop.control.paths import Path, PathPoint


class StateLike(Protocol):
    """What a controller reads of a ``RobotState`` (``wmr_mujoco.drive``)."""

    @property
    def pose(self) -> np.ndarray:
        """``(x, y, ψ)``, m, m, rad."""

    @property
    def twist(self) -> np.ndarray:
        """Body-frame ``(u, v, r)``, m/s, m/s, rad/s."""

    @property
    def extra(self) -> Mapping[str, float]:
        """Robot-specific quantities by name."""


class CommandKind(enum.Enum):
    """The natural command spaces a controller can write (module docstring)."""

    UNICYCLE = "unicycle"
    CAR = "car"
    HOLONOMIC = "holonomic"
    WHIPPLE = "whipple"


def wrap(angle: float) -> float:
    """``angle`` wrapped into ``(−π, π]`` (:func:`wmr_mujoco.analytic.planar.wrap_angle`)."""
    return float(wrap_angle(angle))


def clip(value: float, low: float, high: float) -> float:
    """``value`` clipped to ``[low, high]``: ``np.clip``'s number without its per-call cost."""
    return min(max(value, low), high)


def positive(name: str, value: float) -> float:
    """``value`` if it is a finite real number > 0, else ``ValueError`` naming it."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)) \
            or not math.isfinite(value) or value <= 0:
        raise ValueError(f"{name} = {value!r}; must be a finite number > 0")
    return float(value)


@dataclass(frozen=True)
class Trajectory:
    """A path travelled at constant speed from its start: the reference of trackers.

    At time ``t`` the reference is the path point at ``s = speed · t`` with heading
    ``ψ_r``, speed ``v_r = speed`` and yaw rate ``ω_r = v_r κ(s)``.
    """

    path: Path
    speed: float

    def __post_init__(self) -> None:
        positive("speed", self.speed)

    def at(self, t: float) -> tuple[PathPoint, float, float]:
        """``(point, v_r, ω_r)`` at time ``t``."""
        point = self.path.at(self.speed * t)
        return point, self.speed, self.speed * point.curvature

    @property
    def duration(self) -> float:
        """Time to the end of the path (one lap of a closed one), s."""
        return self.path.length / self.speed


def steer_command(kind: CommandKind, speed: float, steer: float,
                  wheelbase: float) -> np.ndarray:
    """A steering angle ``δ`` (wheelbase ℓ) at speed ``v`` written in ``kind``'s space.

    ``CAR``: ``(v, δ)``; ``UNICYCLE``: ``(v, v tan δ / ℓ)``.

    Raises:
        ValueError: ``kind`` is neither.
    """
    if kind is CommandKind.CAR:
        return np.array([speed, steer])
    if kind is CommandKind.UNICYCLE:
        return np.array([speed, speed * math.tan(steer) / wheelbase])
    raise ValueError(f"a steering controller writes car or unicycle commands, not {kind.value}")


def command_kind(value: CommandKind | str) -> CommandKind:
    """``value`` as a :class:`CommandKind` (by value string).

    Raises:
        ValueError: an unknown kind; the message lists the valid ones.
    """
    if isinstance(value, CommandKind):
        return value
    try:
        return CommandKind(value)
    except ValueError:
        raise ValueError(f"unknown command kind {value!r}; valid kinds: "
                         f"{', '.join(k.value for k in CommandKind)}") from None


class Controller(ABC):
    """A feedback law ``(state, reference, t) -> command`` (module docstring).

    Attributes:
        name: registry name.
        kinds: the command spaces it can write.
        reference_type: what it tracks: ``"pose"``, ``"path"``, ``"trajectory"`` or
            ``"upright"`` (None as reference).
        kind: the command space it writes (one of ``kinds``).
    """

    name: ClassVar[str]
    kinds: ClassVar[tuple[CommandKind, ...]]
    reference_type: ClassVar[str]

    def __init__(self, kind: CommandKind | str) -> None:
        kind = command_kind(kind)
        if kind not in self.kinds:
            raise ValueError(f"controller {self.name!r} writes {[k.value for k in self.kinds]} "
                             f"commands, not {kind.value!r}")
        self.kind = kind
        self.reset()

    def reset(self) -> None:  # noqa: B027 - most controllers hold no state
        """Forget what the controller remembers between calls (progress along a path)."""

    def tracking_point(self, pose: np.ndarray) -> np.ndarray:
        """The point of the robot the law steers onto the path: the pose's ``(x, y)``."""
        return np.asarray(pose, float)[:2]

    @abstractmethod
    def __call__(self, state: StateLike, reference: Any, t: float) -> np.ndarray:
        """The command at time ``t`` (s since reset)."""
