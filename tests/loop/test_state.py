"""The command space's checks."""

from __future__ import annotations

import numpy as np
import pytest

from wmr_mujoco.loop.state import CommandSpace

SPACE = CommandSpace(("v", "omega"), ("m/s", "rad/s"), np.array([-1.0, -2.0]),
                     np.array([1.0, 2.0]))


@pytest.mark.parametrize("command", [(0.5, 1.0), [0, 1], np.array([0.5, 1.0]),
                                     np.array([0.5, 1.0], dtype=np.float32),
                                     np.array([3, 4])])
def test_accepts_two_numbers_in_any_container(command: object) -> None:
    out = SPACE.check(command)
    assert out.dtype == np.float64 and out.shape == (2,)
    np.testing.assert_array_equal(out, np.asarray(command, float))


@pytest.mark.parametrize(("command", "match"), [
    ((1.0,), r"shape \(1,\); expected \(2,\): v in \[-1, 1\] m/s, omega in \[-2, 2\] rad/s"),
    (np.zeros((2, 1)), r"shape \(2, 1\)"),
    ((1.0, float("nan")), "not finite"),
    ((1.0, float("inf")), "not finite"),
    (("a", 1.0), "not numeric"),
    (None, "shape"),
])
def test_rejects_bad_commands(command: object, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        SPACE.check(command)


def test_shape_and_description() -> None:
    assert SPACE.shape == (2,)
    assert SPACE.describe() == "v in [-1, 1] m/s, omega in [-2, 2] rad/s"
