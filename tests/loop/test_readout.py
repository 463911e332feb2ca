"""Placing robots and reading their state from MuJoCo."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest

import wmr_mujoco as wmr
from wmr_mujoco.drive import make
from wmr_mujoco.loop.readout import place, wheel_of_body
from wmr_mujoco.validation.adapters import base_pose, body_twist


@pytest.mark.parametrize("name", ["diffdrive", "bicycle", "disc"])  # free, planar, planar
def test_place_puts_the_base_at_the_pose(name: str) -> None:
    model = wmr.load(name)
    data = mujoco.MjData(model)
    place(model, data, np.array([1.5, -2.0, 2.5]))
    np.testing.assert_allclose(base_pose(model, data), (1.5, -2.0, 2.5), atol=1e-12)


def test_place_turns_a_free_joint_velocity_with_the_body() -> None:
    model = wmr.load("whipple")
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.keyframe("rolling").id)
    speed = float(np.linalg.norm(data.qvel[:2]))
    place(model, data, np.array([0.0, 0.0, math.pi / 2]))
    np.testing.assert_allclose(data.qvel[:2], (0.0, speed), atol=1e-12)


def test_the_discs_steering_target_follows_its_heading() -> None:
    """The disc's heading is its steering hinge: a reset turns the servo's target with it,
    so it does not swing back (heading held within the settling's round-off)."""
    robot = make("disc")
    robot.reset(pose=(0.0, 0.0, 0.4))
    for _ in range(10):
        state = robot.step((0.0, 0.0))
    assert state.pose[2] == pytest.approx(0.4, abs=1e-6)


def test_rollers_belong_to_their_wheel() -> None:
    model = wmr.load("omni3")
    table = wheel_of_body(model, ("wheel1", "wheel2", "wheel3"))
    for k in (1, 2, 3):
        for i in range(12):
            body = model.body(f"wheel{k}_roller{i // 6}{i % 6}").id
            assert table[body] == k - 1
    assert table[model.body("platform").id] == -1


def test_state_matches_the_validation_readers() -> None:
    """Pose and twist as the validation runner reads them, at the end of the period."""
    robot = make("omni3")
    robot.reset(pose=(0.2, 0.1, -0.5))
    for _ in range(10):
        state = robot.step((0.3, 0.1, 0.8))
    m, d = robot.model, robot.data
    mujoco.mj_forward(m, d)
    np.testing.assert_allclose(state.pose, base_pose(m, d), atol=1e-12)
    np.testing.assert_allclose(state.twist, body_twist(m, d), atol=1e-12)
    dofs = [m.jnt_dofadr[m.joint(w).id] for w in robot.wheel_names]
    np.testing.assert_array_equal(state.wheel_rates, d.qvel[dofs])


def _contacts_now(robot: object) -> list[bool]:
    """Whether each wheel touches something now, from ``data.contact`` directly."""
    m, d = robot.model, robot.data
    table = wheel_of_body(m, robot.wheel_names)
    out = [False] * len(robot.wheel_names)
    for g1, g2 in d.contact.geom:
        for g in (g1, g2):
            if table[m.geom_bodyid[g]] >= 0:
                out[table[m.geom_bodyid[g]]] = True
    return out


@pytest.mark.parametrize("name", ["tricycle", "omni3"])  # steering; rollers
def test_a_state_keeps_the_values_of_its_instant(name: str) -> None:
    """The state's arrays are made when first read, from readings taken at its step:
    read after ten more steps, they equal what ``data`` held then (exactly)."""
    robot = make(name)
    robot.reset()
    command = 0.2 * robot.command_space.high
    m, d = robot.model, robot.data
    state = robot.step(command)
    wheels = d.qvel[[m.jnt_dofadr[m.joint(w).id] for w in robot.wheel_names]].copy()
    steers = d.qpos[[m.jnt_qposadr[m.joint(s).id] for s in robot.steer_names]].copy()
    contacts, pose = _contacts_now(robot), base_pose(m, d)
    for _ in range(10):
        robot.step(command)
    np.testing.assert_array_equal(state.wheel_rates, wheels)
    np.testing.assert_array_equal(state.steer_angles, steers)
    assert state.wheel_contacts.tolist() == contacts
    np.testing.assert_allclose(state.pose, pose, atol=1e-12)  # atan2 unwrapped vs folded
    assert float(state.time) == pytest.approx(robot.control_period, abs=1e-12)


def test_a_state_is_frozen_and_its_arrays_are_kept() -> None:
    import copy
    import dataclasses

    from wmr_mujoco.drive import RobotState

    robot = make("diffdrive")
    robot.reset()
    state = robot.step((0.2, 0.1))
    assert isinstance(state, RobotState)
    assert state.pose is state.pose and state.twist.base is state.pose.base
    with pytest.raises(dataclasses.FrozenInstanceError):
        state.pose = np.zeros(3)  # type: ignore[misc]
    with pytest.raises(AttributeError, match="no attribute 'speed'"):
        state.speed  # noqa: B018
    twin = copy.copy(state)  # a plain RobotState of the same arrays
    assert type(twin) is RobotState
    for field in dataclasses.fields(RobotState):
        assert getattr(twin, field.name) is getattr(state, field.name)


def test_read_gives_the_state_of_the_readers_own_data() -> None:
    """``Reader.read`` (the learning environments re-read a state after a task's start)."""
    robot = make("diffdrive")
    state = robot.reset(pose=(0.1, 0.2, 0.3))
    again = robot.reader.read(robot.data, 0.0, 0.3)
    for field in ("pose", "twist", "wheel_rates", "wheel_contacts"):
        np.testing.assert_array_equal(getattr(again, field), getattr(state, field))
    with pytest.raises(ValueError, match="only the MjData it was made with"):
        robot.reader.read(mujoco.MjData(robot.model), 0.0, 0.3)
