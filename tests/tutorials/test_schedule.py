"""Segment schedules: trapezoid speeds, held steering rates, clear errors."""

from __future__ import annotations

import numpy as np
import pytest

from wmr_mujoco.tutorials.schedule import Segment, segment_inputs


def test_trapezoid_and_steering_rate() -> None:
    speed, steer, duration = segment_inputs([(1.0, 0.5, 2.0), (-0.5, -1.0, 1.0)], ramp=0.25)
    assert duration == 3.0
    assert speed(0.0) == 0.0 and speed(0.125) == pytest.approx(0.5)      # half-way up
    assert speed(1.0) == 1.0 and speed(1.875) == pytest.approx(0.5)      # half-way down
    assert speed(2.5) == -0.5 and steer(2.5) == -1.0 and steer(0.1) == 0.5
    assert speed(3.0) == 0.0 and steer(3.0) == 0.0 and speed(-0.1) == 0.0
    # Distance of a trapezoid segment: v (T − ramp).
    t = np.linspace(0.0, 2.0, 200001)
    assert np.trapezoid([speed(x) for x in t], t) == pytest.approx(1.75, rel=1e-6)


def test_triangle_when_shorter_than_two_ramps() -> None:
    speed, _, _ = segment_inputs([Segment(1.0, 0.0, 0.2)], ramp=0.3)
    assert speed(0.1) == pytest.approx(1 / 3)


@pytest.mark.parametrize("segments, match", [
    ([], "non-empty"), ("abc", "non-empty"), ([(1.0, 0.0)], "segments\\[0\\]"),
    ([(1.0, 0.0, 0.0)], "duration"), ([(float("nan"), 0.0, 1.0)], "speed"),
    ([("1", 0.0, 1.0)], "speed"),
])
def test_bad_segments(segments: object, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        segment_inputs(segments)  # type: ignore[arg-type]


@pytest.mark.parametrize("ramp", [0.0, -1.0, float("inf"), "0.3", True])
def test_bad_ramp(ramp: object) -> None:
    with pytest.raises(ValueError, match="ramp"):
        segment_inputs([(1.0, 0.0, 1.0)], ramp=ramp)  # type: ignore[arg-type]
