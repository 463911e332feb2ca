"""What a driven robot reports (:class:`RobotState`) and what it accepts (:class:`CommandSpace`)."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np


@dataclass(frozen=True)
class RobotState:
    """The robot at one instant; every field a numpy array (``extra``: floats).

    Attributes:
        time: s since the last reset (0-d array).
        pose: ``(x, y, heading)`` of the robot's ``base`` site, m, m, rad; the heading is
            unwrapped (continuous over the run, not folded into (−π, π]).
        twist: body-frame ``(u, v, r)``: forward and leftward speed of the ``base`` site
            and yaw rate, m/s, m/s, rad/s.
        wheel_rates: rad/s, one per wheel of ``robot.wheel_names``.
        steer_angles: rad, one per steering joint of ``robot.steer_names`` (empty if none).
        wheel_contacts: whether each wheel touches the floor (bool per wheel; always True
            on the analytic backends, whose wheels roll by assumption).
        extra: robot-specific quantities by name (e.g. the Whipple bicycle's ``lean``,
            rad, and ``lean_rate``, rad/s).
    """

    time: np.ndarray
    pose: np.ndarray
    twist: np.ndarray
    wheel_rates: np.ndarray
    steer_angles: np.ndarray
    wheel_contacts: np.ndarray
    extra: Mapping[str, float] = field(default_factory=lambda: MappingProxyType({}))


@dataclass(frozen=True)
class CommandSpace:
    """The commands a robot accepts: a box ``low <= command <= high``.

    Attributes:
        names: channel names.
        units: their units.
        low: lower bounds (float array).
        high: upper bounds (float array).
    """

    names: tuple[str, ...]
    units: tuple[str, ...]
    low: np.ndarray
    high: np.ndarray

    @property
    def shape(self) -> tuple[int]:
        """``(number of channels,)``."""
        return (len(self.names),)

    def check(self, command: Sequence[float] | np.ndarray) -> np.ndarray:
        """``command`` as a float array of this space's shape (not clipped).

        Raises:
            ValueError: wrong length, or a non-finite or non-numeric value; the message
                names the channels.
        """
        if type(command) is np.ndarray and command.shape == self.shape:
            values = command.tolist()
            if all(type(v) is float and math.isfinite(v) for v in values):
                return command if command.dtype == np.float64 else np.array(values)
        try:
            arr = np.asarray(command, dtype=float)
        except (TypeError, ValueError):
            raise ValueError(f"command {command!r} is not numeric; expected "
                             f"{len(self.names)} numbers {self.describe()}") from None
        if arr.shape != self.shape:
            raise ValueError(f"command {command!r} has shape {arr.shape}; expected "
                             f"{self.shape}: {self.describe()}")
        if not np.all(np.isfinite(arr)):
            raise ValueError(f"command {command!r} is not finite; expected finite "
                             f"{self.describe()}")
        return arr

    def describe(self) -> str:
        """``name [low, high] unit`` of every channel."""
        return ", ".join(f"{n} in [{lo:g}, {hi:g}] {u}" for n, u, lo, hi in
                         zip(self.names, self.units, self.low, self.high, strict=True))
