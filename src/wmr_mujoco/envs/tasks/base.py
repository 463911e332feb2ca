"""The task interface shared by the Gymnasium environments and the dm_control suite.

A task samples an episode (goal, path or speed), reads a robot's :class:`RobotState`
(``wmr_mujoco.drive``), and returns its part of the observation, its reward terms one by
one, and whether the episode succeeded or failed. The reward is the sum of the terms.
Lengths scale with the robot (``scale``, m, from its registry entry's
:class:`~wmr_mujoco.robots.learning.Learning`).
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from wmr_mujoco.analytic.planar import wrap_angle


@dataclass(frozen=True)
class Field:
    """One named block of an observation vector.

    Attributes:
        name: what it is.
        size: number of entries.
        unit: SI unit (or ``1``).
    """

    name: str
    size: int
    unit: str


#: Longest distance a task spans, m (a goal's arena, a path's length): the paths are
#: sampled every 2 cm, so this bounds an episode's path at 5·10⁴ points.
MAX_LENGTH = 1000.0

#: Weight of the effort term, ``effort = −EFFORT mean(a²)``.
EFFORT = 0.01


def effort(action: Sequence[float]) -> float:
    """``−EFFORT mean(a²)`` of a normalised action (floats, or an array)."""
    total = 0.0
    for a in action:
        total += a * a
    return -EFFORT * float(total) / len(action)


def wrap(angle: float) -> float:
    """Angle wrapped to ``(-π, π]``, rad (:func:`wmr_mujoco.analytic.planar.wrap_angle`)."""
    return float(wrap_angle(angle))


def pose_of(state: Any) -> tuple[float, float, float]:
    """``(x, y, ψ)`` of a state, floats: an environment's snapshot's own, else its pose's."""
    xyh = getattr(state, "xyh", None)
    return xyh if xyh is not None else tuple(state.pose.tolist()[:3])


def speed_of(state: Any) -> float:
    """Forward speed ``u`` of a state, m/s (a snapshot's float, else its twist's)."""
    uvr = getattr(state, "uvr", None)
    return uvr[0] if uvr is not None else float(state.twist[0])


def to_body(pose: np.ndarray, xy: np.ndarray) -> np.ndarray:
    """World points ``xy`` (…, 2) in the body frame of ``pose = (x, y, ψ)``: ``Rᵀ(ψ)(p − p₀)``."""
    x, y, psi = (float(v) for v in pose[:3])
    c, s = math.cos(psi), math.sin(psi)
    xy = np.asarray(xy, float)
    if xy.ndim == 1:  # one point: plain floats (the environments' hot path)
        dx, dy = float(xy[0]) - x, float(xy[1]) - y
        return np.array([c * dx + s * dy, -s * dx + c * dy])
    d = xy - np.array([x, y])
    return np.stack([c * d[..., 0] + s * d[..., 1], -s * d[..., 0] + c * d[..., 1]], axis=-1)


class Task(ABC):
    """One learning task on one robot.

    Subclasses set :attr:`name`, :attr:`fields` and implement the abstract methods; their
    keyword arguments (the task's options) are checked in ``__init__``.
    """

    name: ClassVar[str]
    #: Episode length, s (the episode is truncated there).
    time_limit: float
    #: The task's observation blocks, in order.
    fields: tuple[Field, ...]

    def __init__(self, scale: float, max_curvature: float) -> None:
        self.scale = scale
        self.max_curvature = max_curvature

    @property
    def size(self) -> int:
        """Length of the task's observation block."""
        return sum(f.size for f in self.fields)

    @abstractmethod
    def sample(self, rng: np.random.Generator) -> np.ndarray:
        """Draw a new episode; return the start pose ``(x, y, ψ)``."""

    def start(self, robot: Any, rng: np.random.Generator) -> None:  # noqa: B027
        """Set the robot's initial motion after ``robot.reset`` (default: at rest)."""

    @abstractmethod
    def observe(self, state: Any) -> list[float]:
        """The task's observation block (:attr:`size` floats)."""

    @abstractmethod
    def reward_terms(self, prev: Any, state: Any, action: Sequence[float], dt: float
                     ) -> dict[str, float]:
        """The reward terms of one step from ``prev`` to ``state`` under ``action``.

        A new dict every step (the environments hand it out in ``info``).
        """

    @abstractmethod
    def outcome(self, state: Any) -> tuple[bool, bool]:
        """``(success, failure)`` now: either ends the episode (terminated)."""

    def evaluate(self, prev: Any, state: Any, action: Sequence[float], dt: float
                 ) -> tuple[dict[str, float], bool, bool]:
        """``(reward_terms(...), *outcome(state))`` of one step, in one call.

        A task may override it to share the work of both (the environments' hot path);
        the result must equal the two calls'.
        """
        return (self.reward_terms(prev, state, action, dt), *self.outcome(state))

    def evaluate_observe(self, prev: Any, state: Any, action: Sequence[float], dt: float
                         ) -> tuple[dict[str, float], bool, bool, list[float]]:
        """``(*evaluate(...), observe(state))`` of one step, in one call.

        A task may override it to share the work (the environments' hot path); the result
        must equal the two calls'.
        """
        terms, success, failure = self.evaluate(prev, state, action, dt)
        return terms, success, failure, self.observe(state)

    def succeeded_at_time_limit(self, state: Any) -> bool:
        """Whether an episode that runs to its time limit counts as a success (default no)."""
        return False


def check_options(task: str, given: Mapping[str, Any], valid: Mapping[str, Any],
                  lengths: tuple[str, ...] = ()) -> dict:
    """Merge ``given`` into the defaults ``valid``; every value a positive finite number.

    The options named in ``lengths`` (m) must not exceed :data:`MAX_LENGTH`.

    Raises:
        ValueError: an unknown option (the valid names listed) or a bad value.
    """
    unknown = sorted(set(given) - set(valid))
    if unknown:
        raise ValueError(f"unknown option(s) {unknown} for task {task!r}; valid options: "
                         f"{', '.join(f'{k}={v!r}' for k, v in valid.items())}")
    out = {**valid, **given}
    for key, value in out.items():
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not (
                math.isfinite(value) and value > 0):
            raise ValueError(f"task {task!r}: option {key}={value!r} must be a positive "
                             "finite number")
        if key in lengths and value > MAX_LENGTH:
            raise ValueError(f"task {task!r}: option {key}={value!r} m is above the "
                             f"{MAX_LENGTH:g} m a task may span")
    return out
