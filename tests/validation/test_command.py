"""Command maps: the servo law, the command box, the linear fast path, their checks."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import wmr_mujoco as wmr
from wmr_mujoco.robots import ROBOTS, get_spec
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams
from wmr_mujoco.validation.command import RateCommand, TorqueCommand, servo_rate


@pytest.mark.parametrize(("command", "target", "expected"), [
    (0.05, 0.0, 2.5),      # reaches in one period: (0.05 − 0) / 0.02
    (0.5, 0.0, 3.0),       # rate limit
    (-0.5, 0.2, -3.0),     # rate limit, other sign
    (0.1, 0.1, 0.0),       # there: hold
])
def test_servo_rate_is_the_clipped_rate_that_lands_in_one_period(command: float,
                                                                 target: float,
                                                                 expected: float) -> None:
    assert servo_rate(command, target, 0.02, 3.0) == pytest.approx(expected, rel=1e-12)


RATE = [n for n, s in ROBOTS.items() if isinstance(s.command, RateCommand)]


@pytest.mark.parametrize("name", RATE)
def test_the_command_box_keeps_every_wheel_inside_its_rate_limit(name: str) -> None:
    """At every corner of the box the wheel controls stay within their ctrl range, and
    one corner reaches a limit (the box is as large as it can be with this shape)."""
    cmap = ROBOTS[name].command
    model = wmr.load(name)
    adapter = cmap.analytic(None)
    low, high = cmap.limits(model, adapter)
    servo = {s.channel for s in cmap.servo}
    steer_acts = {model.actuator(s.actuator).id for s in cmap.servo}
    wheels = [i for i in range(model.nu) if i not in steer_acts]
    rest = np.zeros(len(adapter.state_names))
    worst = 0.0
    rate = [j for j in range(len(low)) if j not in servo]
    for signs in itertools.product((-1.0, 1.0), repeat=len(rate)):
        u = np.zeros(len(low))
        u[rate] = np.where(np.array(signs) > 0, high[rate], low[rate])
        ctrl = adapter.controls(cmap.inputs(adapter, u, np.zeros(len(servo)), 1.0,
                                            np.zeros(len(servo))), rest)
        worst = max(worst, np.max(np.abs(ctrl[wheels]) / model.actuator_ctrlrange[wheels, 1]))
    assert worst == pytest.approx(1.0, rel=1e-9)
    for s in cmap.servo:  # steering angles: the servo's own angle range
        np.testing.assert_array_equal((low[s.channel], high[s.channel]),
                                      model.actuator(s.actuator).actrange)


def test_diffdrive_matrix_is_the_unicycle_wheel_map() -> None:
    """``θ̇_{L,R} = (v ∓ ω b/2) / R``."""
    p = DiffDriveParams()
    w = get_spec("diffdrive").command.matrix(get_spec("diffdrive").command.analytic(None))
    r, b = p.wheel.radius, p.track
    np.testing.assert_allclose(w, [[1 / r, -b / (2 * r)], [1 / r, b / (2 * r)]], rtol=1e-12)


def test_state_dependent_controls_have_no_matrix() -> None:
    cmap = get_spec("double_steer").command
    assert cmap.matrix(cmap.analytic(None)) is None


def test_malformed_command_maps_are_refused() -> None:
    with pytest.raises(ValueError, match="names .* and units .* differ"):
        TorqueCommand(("a", "b"), ("N·m",), wheels=(), actuators=("a", "b"))
    with pytest.raises(ValueError, match="one actuator per channel"):
        TorqueCommand(("a", "b"), ("N·m", "N·m"), wheels=(), actuators=("a",))
    with pytest.raises(ValueError, match="give the kinematic adapter"):
        RateCommand(("v",), ("m/s",), wheels=())
