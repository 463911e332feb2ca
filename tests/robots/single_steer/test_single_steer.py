"""The (2,1) robot's registry entry: actuator order and the sleigh state read at rest."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.robots import single_steer
from wmr_mujoco.robots.single_steer.params import SingleSteerParams


def _adapter(model):
    return single_steer.sleigh_adapter(single_steer.SCENARIOS[0], model, None)


def test_controls_follow_the_actuator_order():
    model = load("single_steer")
    assert [model.actuator(i).name for i in range(model.nu)] == ["drive_wheel", "drive_steer"]
    ctrl = _adapter(model).controls(np.array([0.4, 0.2]), np.zeros(5))
    assert ctrl == pytest.approx([0.4 / SingleSteerParams().wheel.radius, 0.2])


def test_sim_state_reads_the_settled_robot_at_rest():
    model = load("single_steer")
    data = mujoco.MjData(model)
    for _ in range(100):
        mujoco.mj_step(model, data)
    x = _adapter(model).sim_state(model, data)
    # At rest: heading, steering angle and momentum are (numerically) zero.
    assert np.abs(x[2:]) == pytest.approx(np.zeros(3), abs=1e-6)
