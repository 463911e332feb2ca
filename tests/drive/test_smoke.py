"""Every drivable robot makes, resets and steps on each of its backends."""

from __future__ import annotations

import numpy as np
import pytest

from wmr_mujoco.drive import RobotState, make
from wmr_mujoco.robots import ROBOTS

DRIVABLE = [name for name, spec in ROBOTS.items() if spec.command is not None]
CASES = [(name, backend) for name in DRIVABLE for backend in ("mujoco", "kinematic")
         if backend == "mujoco" or ROBOTS[name].command.analytic(None) is not None]


@pytest.mark.parametrize(("name", "backend"), CASES)
def test_steps_within_the_command_space(name: str, backend: str) -> None:
    robot = make(name, backend=backend, control_period=0.02)
    space = robot.command_space
    state = robot.reset(pose=(0.3, -0.2, 0.4), seed=1)
    assert isinstance(state, RobotState)
    # Starts where asked: settling moves the base by far less than a millimetre.
    np.testing.assert_allclose(state.pose, (0.3, -0.2, 0.4), atol=1e-3)
    command = 0.1 * space.high  # a tenth of every limit: inside the box
    for _ in range(5):
        state = robot.step(command)
    assert state.time == pytest.approx(5 * 0.02)
    assert robot.time == pytest.approx(0.1)
    assert len(robot.history) == 6
    assert state.wheel_rates.shape == (len(robot.wheel_names),)
    assert state.steer_angles.shape == (len(robot.steer_names),)
    assert state.wheel_contacts.dtype == bool
    for field in ("pose", "twist", "wheel_rates", "steer_angles"):
        assert np.all(np.isfinite(getattr(state, field))), field
    assert (robot.model is None) == (backend != "mujoco")
