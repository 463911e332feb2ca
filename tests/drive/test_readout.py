"""Placing robots and reading their state from MuJoCo."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest

import wmr_mujoco as wmr
from wmr_mujoco.drive import make
from wmr_mujoco.drive.readout import place, wheel_of_body
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
