"""The shared part of every backend: input checks, clipping, clock, history, reset."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import wmr_mujoco as wmr
from wmr_mujoco.drive import make
from wmr_mujoco.loop.robot import substeps
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams
from wmr_mujoco.sim.stepping import SimulationDivergedError


def test_make_is_exported_lazily_from_the_package() -> None:
    robot = wmr.make("diffdrive")
    assert isinstance(robot.command_space, wmr.CommandSpace)
    assert isinstance(robot.reset(), wmr.RobotState)


@pytest.mark.parametrize(("kwargs", "match"), [
    ({"robot": "hexapod"}, "unknown robot 'hexapod'; valid robots are: disc"),
    ({"backend": "bullet"}, "unknown backend 'bullet'; valid backends are: mujoco, kinematic"),
    ({"mode": "velocity"}, "unknown mode 'velocity'; valid modes are: command, wheels"),
    ({"control_period": 0.016}, r"control_period = 0.016 s is not a multiple of the model "
                                r"timestep 0.0025 s"),
    ({"control_period": 0.0}, r"must be in \(0, 10\] s"),
    ({"control_period": 1e5}, r"must be in \(0, 10\] s"),  # one step() would run for minutes
    ({"control_period": float("nan")}, r"must be in \(0, 10\] s"),
    ({"control_period": 0.0005}, "not a multiple of the model timestep 0.0025"),
    ({"backend": "kinematic", "mode": "wheels"}, "kinematic backend takes mode='command'"),
    ({"params": object()}, "params must be a DiffDriveParams, got object"),
])
def test_bad_arguments_are_refused(kwargs: dict, match: str) -> None:
    args = {"robot": "diffdrive", **kwargs}
    with pytest.raises(ValueError, match=match):
        make(args.pop("robot"), **args)


def test_a_control_period_that_is_not_a_number_is_a_type_error() -> None:
    with pytest.raises(TypeError, match="control_period = '0.02'"):
        make("diffdrive", control_period="0.02")
    with pytest.raises(TypeError, match="control_period = True"):
        substeps(True, 0.002)


def test_torque_mode_is_refused_for_a_model_with_its_own_actuators() -> None:
    with pytest.raises(ValueError, match="'whipple' keeps its own actuators"):
        make("whipple", mode="torque")


@pytest.mark.parametrize("backend", ["mujoco", "kinematic"])
def test_bad_reset_and_step_inputs_raise_before_any_change(backend: str) -> None:
    robot = make("diffdrive", backend=backend)
    with pytest.raises(RuntimeError, match=r"call robot.reset\(\) before robot.step\(\)"):
        robot.step((0.1, 0.0))
    with pytest.raises(RuntimeError, match="no state yet"):
        _ = robot.state
    for pose in [(0.0, 0.0), (0.0, 0.0, float("nan")), "abc", (1, 2, 3, 4)]:
        with pytest.raises(ValueError, match="expected three finite numbers"):
            robot.reset(pose=pose)
    for seed in [-1, 1.5, "7", True]:
        with pytest.raises(ValueError, match="expected None or an integer >= 0"):
            robot.reset(seed=seed)
    robot.reset()
    robot.step((0.2, 0.1))
    before = robot.state
    for command in [(0.1,), (0.1, float("inf")), (0.1, None), "ab"]:
        with pytest.raises(ValueError, match="command"):
            robot.step(command)
    assert robot.state is before and len(robot.history) == 2


@pytest.mark.parametrize("backend", ["mujoco", "kinematic"])
def test_out_of_range_commands_are_clipped_with_one_warning(backend: str) -> None:
    clipped, limit = make("diffdrive", backend=backend), make("diffdrive", backend=backend)
    clipped.reset()
    limit.reset()
    high = clipped.command_space.high
    with pytest.warns(UserWarning, match=r"command \[16.0, 0.0\] outside the command space "
                                         r"\(v in \[-1.6, 1.6\] m/s"):
        a = clipped.step((10 * high[0], 0.0))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a second warning would fail here
        a = clipped.step((10 * high[0], 0.0))
        b = limit.step((high[0], 0.0))
        b = limit.step((high[0], 0.0))
    # Clipped to the limit: bit for bit the run at the limit (both runs deterministic).
    np.testing.assert_array_equal(a.pose, b.pose)
    np.testing.assert_array_equal(clipped.commands[0], (high[0], 0.0))


def test_heading_is_unwrapped_over_turns() -> None:
    robot = make("diffdrive")
    robot.reset(pose=(0.0, 0.0, 3.0))
    rate = 0.5 * robot.command_space.high[1]
    for _ in range(100):  # 2 s: more than a turn at 4.4 rad/s
        state = robot.step((0.0, rate))
    headings = np.array([s.pose[2] for s in robot.history])
    # Continuous: no jump of 2π between periods (a step turns |r| T < 0.1 rad).
    assert np.max(np.abs(np.diff(headings))) < 0.2
    assert state.pose[2] > 3.0 + math.pi


def test_reset_starts_the_clock_and_the_history_again() -> None:
    robot = make("omni3")
    robot.reset()
    for _ in range(3):
        robot.step((0.1, 0.0, 0.0))
    state = robot.reset(pose=(1.0, 1.0, 0.0))
    assert robot.time == 0.0 and robot.history == [state] and robot.commands == []


def test_a_seed_draws_the_wheel_phases_reproducibly() -> None:
    def wheel_angles(seed: int | None) -> np.ndarray:
        robot = make("omni3")
        robot.reset(seed=seed)
        return robot.data.qpos[robot._wheel_qpos].copy()

    np.testing.assert_array_equal(wheel_angles(3), wheel_angles(3))
    assert not np.allclose(wheel_angles(3), wheel_angles(4))
    # Without a seed every wheel starts at 0 (plus the settling's tiny turn).
    np.testing.assert_allclose(wheel_angles(None), 0.0, atol=1e-3)


def test_a_diverging_run_raises() -> None:
    robot = make("diffdrive")
    robot.reset()
    robot.data.qvel[0] = 1e12  # beyond MuJoCo's mjMAXVAL: its velocity check warns
    with pytest.raises(SimulationDivergedError, match="BADQVEL"):
        robot.step((0.1, 0.0))


def test_params_build_the_robot_from_parameters() -> None:
    wide = DiffDriveParams(track=0.5)
    robot = make("diffdrive", backend="kinematic", params=wide)
    robot.reset()
    state = robot.step((0.0, 1.0))
    # Turning in place at ω the wheels roll at ∓ω b/2 / R (b the track).
    np.testing.assert_allclose(state.wheel_rates, np.array([-1.0, 1.0]) * 0.25
                               / wide.wheel.radius, rtol=1e-12)


@pytest.mark.parametrize("command", [np.array([0.2, 0.1]), [0.2, 0.1], (0.2, 0.1), [0, 1],
                                     np.array([0.2, 0.1], dtype=np.float32),
                                     np.array([[0.2, 0.1]])[0, :]])
def test_the_recorded_command_is_the_robots_own_copy(command: object) -> None:
    """Every way in (the fast path for floats inside the box, the full check otherwise)
    records a float64 copy: changing the caller's container later changes nothing."""
    robot = make("diffdrive")
    robot.reset()
    robot.step(command)
    expected = np.asarray(command, float).copy()
    if isinstance(command, (np.ndarray, list)):
        command[0] = 9.0
    recorded = robot.commands[0]
    assert recorded.dtype == np.float64
    np.testing.assert_array_equal(recorded, expected)
