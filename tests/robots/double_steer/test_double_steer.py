"""The (1,2) robot's registry entry: actuator order, one ICR for both wheel speeds."""

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.robots import double_steer
from wmr_mujoco.robots.double_steer.params import DoubleSteerParams


def _adapter(model):
    return double_steer.kinematic_adapter(double_steer.SCENARIOS[0], model, None)


def test_controls_follow_the_actuator_order_and_share_one_icr():
    model = load("double_steer")
    assert [model.actuator(i).name for i in range(model.nu)] == [
        "front_wheel", "front_steer", "rear_wheel", "rear_steer"]
    p = DoubleSteerParams()
    b1, b2, v1 = 0.4, -0.2, 0.3
    ctrl = _adapter(model).controls(np.array([v1, 0.1, -0.1]), np.array([0, 0, 0, b1, b2]))
    r = p.wheel.radius
    v2 = ctrl[2] * r
    # Rigid chassis: both contact points have the same velocity component along the
    # line joining them (the body x axis): v₁ cos β₁ = v₂ cos β₂.
    assert v1 * math.cos(b1) == pytest.approx(v2 * math.cos(b2), rel=1e-12)
    assert ctrl[[0, 1, 3]] == pytest.approx([v1 / r, 0.1, -0.1])


def test_sim_state_reads_pose_and_steering_at_rest():
    model = load("double_steer")
    data = mujoco.MjData(model)
    for _ in range(100):
        mujoco.mj_step(model, data)
    x = _adapter(model).sim_state(model, data)
    assert np.abs(x[2:]) == pytest.approx(np.zeros(3), abs=1e-6)
