"""Open-loop manoeuvres: segments of constant inputs, as input functions of time.

A manoeuvre is a list of :class:`Segment` ``(speed, steer_rate, duration)``. Within a
segment the steering rate is constant and the speed follows a trapezoid: it ramps from 0
to ``speed`` over ``ramp`` seconds, holds, and ramps back to 0 at the segment's end, so
that a wheel is never asked for a jump of speed (a step makes a real wheel slip, and the
kinematic model then no longer applies). The same functions drive the physics and the
analytic model (``wmr.simulate``, ``wmr.predict``, ``wmr.compare``).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Segment:
    """One segment of a manoeuvre.

    Attributes:
        speed: peak ground speed of the driven wheel, m/s (negative: backwards).
        steer_rate: steering rate ω, rad/s, held over the whole segment.
        duration: seconds, > 0 (at least ``2 ramp`` for the speed to reach its peak).
    """

    speed: float
    steer_rate: float
    duration: float

    def __post_init__(self) -> None:
        for name in ("speed", "steer_rate", "duration"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, float, np.number)) \
                    or not math.isfinite(value):
                raise ValueError(f"Segment.{name} = {value!r}; must be a finite number")
        if self.duration <= 0:
            raise ValueError(f"Segment.duration = {self.duration!r}; must be > 0 s")


def segment_inputs(segments: Sequence[Segment | tuple[float, float, float]],
                   ramp: float = 0.3) -> tuple[Callable[[float], float],
                                               Callable[[float], float], float]:
    """Inputs ``(v(t), ω(t))`` and the total duration of a manoeuvre.

    The speed of each segment is ``speed · min(1, t_s/ramp, (T − t_s)/ramp)`` at time
    ``t_s`` into a segment of duration T (a trapezoid, or a triangle if ``T < 2 ramp``);
    ω is the segment's ``steer_rate``. After the last segment both are 0.

    Args:
        segments: the manoeuvre, as :class:`Segment` or ``(speed, steer_rate, duration)``.
        ramp: seconds of each speed ramp, > 0.

    Returns:
        ``(speed, steer_rate, duration)``: two functions of time (s) and the total time.

    Raises:
        ValueError: an empty manoeuvre, a malformed segment or a bad ramp.
    """
    if isinstance(ramp, bool) or not isinstance(ramp, (int, float)) or not ramp > 0 \
            or not math.isfinite(ramp):
        raise ValueError(f"ramp = {ramp!r}; must be a finite number of seconds > 0")
    if isinstance(segments, (str, bytes)) or not isinstance(segments, Sequence) \
            or not segments:
        raise ValueError(f"segments = {segments!r}; give a non-empty list of "
                         "(speed, steer_rate, duration)")
    segs = []
    for i, s in enumerate(segments):
        if isinstance(s, Segment):
            segs.append(s)
        elif isinstance(s, (tuple, list)) and len(s) == 3:
            segs.append(Segment(*s))
        else:
            raise ValueError(f"segments[{i}] = {s!r}; give (speed, steer_rate, duration)")
    starts = np.concatenate([[0.0], np.cumsum([s.duration for s in segs])])

    def locate(t: float) -> tuple[Segment | None, float]:
        if t < 0.0 or t >= starts[-1]:
            return None, 0.0
        i = int(np.searchsorted(starts, t, side="right")) - 1
        return segs[i], t - starts[i]

    def speed(t: float) -> float:
        seg, ts = locate(t)
        if seg is None:
            return 0.0
        return seg.speed * min(1.0, ts / ramp, (seg.duration - ts) / ramp)

    def steer_rate(t: float) -> float:
        seg, _ = locate(t)
        return 0.0 if seg is None else seg.steer_rate

    return speed, steer_rate, float(starts[-1])
