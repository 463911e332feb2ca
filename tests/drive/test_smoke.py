"""Every registered robot: driven on each backend it has, or refused with a clear error."""

from __future__ import annotations

import numpy as np
import pytest

from wmr_mujoco.drive import RobotState, drivable, make
from wmr_mujoco.robots import ROBOTS

CASES = [(name, backend) for name in drivable() for backend in ("mujoco", "kinematic")
         if backend == "mujoco" or ROBOTS[name].command.analytic(None) is not None]


@pytest.mark.parametrize(("name", "backend"), CASES)
def test_steps_within_the_command_space(name: str, backend: str) -> None:
    robot = make(name, backend=backend, control_period=0.02)
    space = robot.command_space
    assert space.shape == (len(space.names),) == space.low.shape == space.high.shape
    assert np.all(space.low < space.high)
    state = robot.reset(pose=(0.3, -0.2, 0.4), seed=1)
    assert isinstance(state, RobotState)
    # Starts where asked: settling on the soft contacts moves the base by far less than
    # a millimetre (contact penetrations are tenths of a millimetre).
    np.testing.assert_allclose(state.pose, (0.3, -0.2, 0.4), atol=1e-3)
    command = 0.1 * space.high  # a tenth of every limit: inside the box
    for _ in range(5):
        state = robot.step(command)
    assert state.time == pytest.approx(5 * 0.02)
    assert robot.time == pytest.approx(0.1)
    assert len(robot.history) == 6 and len(robot.commands) == 5
    assert state.wheel_rates.shape == state.wheel_contacts.shape == (len(robot.wheel_names),)
    assert state.steer_angles.shape == (len(robot.steer_names),)
    assert state.wheel_contacts.dtype == bool
    for field in ("pose", "twist", "wheel_rates", "steer_angles"):
        assert np.all(np.isfinite(getattr(state, field))), field
    assert (robot.model is None) == (backend != "mujoco")
    arrays = robot.history_arrays()
    assert arrays["pose"].shape == (6, 3) and arrays["time"][-1] == pytest.approx(0.1)


def test_every_robot_but_the_free_disc_can_be_driven() -> None:
    assert sorted(drivable()) == sorted(set(ROBOTS) - {"disc_free"})


def test_the_free_disc_has_no_actuators() -> None:
    with pytest.raises(ValueError, match="'disc_free' has no actuators.*robots that can: "):
        make("disc_free")


def test_whipple_has_no_kinematic_backend() -> None:
    with pytest.raises(ValueError, match="'whipple' has no kinematic model"):
        make("whipple", backend="kinematic")


RAW = [(name, mode) for name in drivable() for mode in ("wheels", "torque")
       if not (mode == "torque" and name == "whipple")]  # whipple: its own torque motors


@pytest.mark.parametrize(("name", "mode"), RAW)
def test_raw_actuator_modes_step(name: str, mode: str) -> None:
    robot = make(name, mode=mode)
    space = robot.command_space
    assert space.names == tuple(robot.model.actuator(i).name for i in range(robot.model.nu))
    robot.reset()
    for _ in range(3):
        state = robot.step(0.1 * space.high)
    assert np.all(np.isfinite(state.pose)) and state.time == pytest.approx(0.06)
