"""Input signals of a scenario, as data: piecewise-linear knots or a sinusoid."""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Piecewise:
    """Piecewise-linear signal through ``knots = ((t0, u0), (t1, u1), ...)``.

    Before ``t0`` it holds ``u0``, after the last knot it holds the last value. Two knots
    at the same time make a step.
    """

    knots: tuple[tuple[float, float], ...]

    def __post_init__(self) -> None:
        times = [k[0] for k in self.knots]
        if not self.knots or any(b < a for a, b in itertools.pairwise(times)):
            raise ValueError(f"knots = {self.knots!r}; need at least one, in time order")

    def __call__(self, t: float) -> float:
        """Value at time ``t``."""
        knots = self.knots
        if t <= knots[0][0]:
            return float(knots[0][1])
        for (t0, u0), (t1, u1) in itertools.pairwise(knots):
            if t < t1:
                return float(u0 + (u1 - u0) * (t - t0) / (t1 - t0)) if t1 > t0 else float(u1)
        return float(knots[-1][1])

    def on(self, times: np.ndarray) -> np.ndarray:
        """Values at every time of ``times``: the floats of ``__call__``, elementwise.

        Each time takes the first segment ``(t0, t1)`` with ``t < t1`` (the segments are
        filled last to first, so the first one wins), the same arithmetic per element.
        """
        t = np.asarray(times, float)
        knots = self.knots
        out = np.full(t.shape, float(knots[-1][1]))
        for (t0, u0), (t1, u1) in reversed(list(itertools.pairwise(knots))):
            hit = t < t1
            out[hit] = u0 + (u1 - u0) * (t[hit] - t0) / (t1 - t0) if t1 > t0 else float(u1)
        out[t <= knots[0][0]] = float(knots[0][1])
        return out


@dataclass(frozen=True)
class Sine:
    """``offset + amplitude · sin(2π t / period + phase)``."""

    amplitude: float
    period: float
    offset: float = 0.0
    phase: float = 0.0

    def __post_init__(self) -> None:
        if not (math.isfinite(self.period) and self.period > 0):
            raise ValueError(f"period = {self.period!r}; must be a finite number > 0")

    def __call__(self, t: float) -> float:
        """Value at time ``t``."""
        return self.offset + self.amplitude * math.sin(2 * math.pi * t / self.period
                                                       + self.phase)

    def on(self, times: np.ndarray) -> np.ndarray:
        """Values at every time of ``times`` (``__call__``'s arithmetic, elementwise)."""
        t = np.asarray(times, float)
        return self.offset + self.amplitude * np.sin(2 * math.pi * t / self.period
                                                     + self.phase)


@dataclass(frozen=True)
class Held:
    """``signal`` up to ``until`` seconds, then its value at ``until`` held for ever."""

    signal: Piecewise | Sine
    until: float

    def __post_init__(self) -> None:
        if not (math.isfinite(self.until) and self.until >= 0):
            raise ValueError(f"until = {self.until!r} s; must be a finite number >= 0")

    def __call__(self, t: float) -> float:
        """Value at time ``t``."""
        return self.signal(min(t, self.until))

    def on(self, times: np.ndarray) -> np.ndarray:
        """Values at every time of ``times``."""
        return self.signal.on(np.minimum(np.asarray(times, float), self.until))


Signal = Piecewise | Sine | Held


def const(value: float, ramp: float = 0.0) -> Piecewise:
    """A constant, reached from zero by a linear ramp of ``ramp`` seconds (0: a step).

    Raises:
        ValueError: ``value`` not finite, or ``ramp`` not a finite number >= 0.
    """
    if not math.isfinite(value):
        raise ValueError(f"value = {value!r}; must be a finite number")
    if not (math.isfinite(ramp) and ramp >= 0):
        raise ValueError(f"ramp = {ramp!r} s; must be a finite number in [0, inf)")
    return Piecewise(((0.0, 0.0), (ramp, value))) if ramp > 0 else Piecewise(((0.0, value),))


def pulses(*segments: tuple[float, float, float]) -> Piecewise:
    """Rectangular pulses ``(start, end, value)`` on a zero background (steps at edges)."""
    knots: list[tuple[float, float]] = [(0.0, 0.0)]
    for start, end, value in sorted(segments):
        knots += [(start, 0.0), (start, value), (end, value), (end, 0.0)]
    return Piecewise(tuple(knots))


def steer_to(angle: float, start: float = 0.0, time: float = 0.5) -> Piecewise:
    """Steering-rate pulse that turns the steering by ``angle`` over ``time`` seconds."""
    return pulses((start, start + time, angle / time))
