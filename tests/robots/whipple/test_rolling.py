"""Start states of the Whipple measurements: steady rolling, the push, the lean angle."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.robots.whipple import rolling
from wmr_mujoco.robots.whipple.params import WhippleParams


@pytest.fixture(scope="module")
def model():
    return rolling.compile_model(WhippleParams())


def test_steady_rolling_is_upright_at_speed(model):
    """After the settle the rear axle moves at the commanded speed (the contacts' settle
    takes < 0.1 %) and the lateral states are exactly zero (mirror symmetry)."""
    data = rolling.steady_rolling(model, None, 5.0)
    assert data.qvel[0] == pytest.approx(5.0, rel=1e-3)
    assert data.qvel[[rolling.Y, rolling.ROLL, rolling.YAW, rolling.STEER]].tolist() == [0.0] * 4
    assert rolling.lean_angle(data.qpos[3:7]) == 0.0 and data.time == 0.0


def test_push_is_a_lean_rate_about_the_ground_line(model):
    """ω_x = φ̇₀ and the point of the rear frame on the floor below the axle does not move
    sideways: v_y + z ω_x = −φ̇₀ z + z φ̇₀ = 0."""
    data = rolling.steady_rolling(model, None, 5.0)
    rolling.push(model, data, 0.5)
    assert data.qvel[rolling.ROLL] == 0.5
    assert data.qvel[rolling.Y] + data.qpos[2] * data.qvel[rolling.ROLL] == pytest.approx(
        0.0, abs=1e-15)


@pytest.mark.parametrize("lean", [-0.4, 0.1, 1.0])
def test_lean_angle_of_a_yawed_and_pitched_frame(lean):
    """Yaw 0.7, then lean, then pitch 0.2 (the benchmark's order): the lean comes back."""
    def axis_angle(axis, angle):
        q = np.zeros(4)
        mujoco.mju_axisAngle2Quat(q, np.asarray(axis, float), angle)
        return q

    q = np.zeros(4)
    tmp = np.zeros(4)
    mujoco.mju_mulQuat(tmp, axis_angle([0, 0, 1], 0.7), axis_angle([1, 0, 0], lean))
    mujoco.mju_mulQuat(q, tmp, axis_angle([0, 1, 0], 0.2))
    assert rolling.lean_angle(q) == pytest.approx(lean, abs=1e-12)


@pytest.mark.parametrize("speed", [-0.1, math.inf, 30.5])
def test_bad_speed_names_the_range(model, speed):
    with pytest.raises(ValueError, match=r"speed = .* m/s; valid range is \[0, 30\]"):
        rolling.steady_rolling(model, None, speed)
