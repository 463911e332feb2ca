"""The centred steerable wheels: steering axis through the wheel centre, vertical."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.robots.steered.builder import fork_yaw_inertia

STEERED = {"single_steer": ("drive",), "double_steer": ("front", "rear")}


@pytest.mark.parametrize("robot", list(STEERED))
def test_steering_axes_pass_through_the_wheel_centres(robot):
    model = load(robot)
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    for prefix in STEERED[robot]:
        steer = model.joint(f"{prefix}_steer").id
        wheel = model.body(f"{prefix}_wheel").id
        np.testing.assert_allclose(data.xaxis[steer], [0, 0, 1], atol=1e-12)
        np.testing.assert_allclose(data.xanchor[steer][:2], data.xpos[wheel][:2], atol=1e-12)
        assert model.actuator(f"{prefix}_wheel") and model.actuator(f"{prefix}_steer")


def test_fork_yaw_inertia_is_that_of_its_box():
    """A 0.04 × 0.06 m box (any height) about its vertical axis: m (a² + b²)/12."""
    assert fork_yaw_inertia(0.3) == pytest.approx(0.3 * (0.04**2 + 0.06**2) / 12.0)
