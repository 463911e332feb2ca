"""omni3's dynamic runs: state extraction against MuJoCo's own functions."""

from types import SimpleNamespace

import mujoco
import numpy as np
import pytest

from wmr_mujoco.models.actuation import ActuationMode, actuation_mode
from wmr_mujoco.robots.omni3.runs import (
    base_states,
    coast_start,
    phase_lag_steps,
    relative,
    settled,
)
from wmr_mujoco.sim.engine import get_state
from wmr_mujoco.validation.adapters import base_pose, body_twist


def test_base_states_match_the_site_functions():
    """Pose and body twist from the free joint's (p, q, v, ω) equal mj_objectVelocity /
    site frame readings of the base site while driving and turning (to rounding)."""
    model, data = settled(ActuationMode.RATE)
    for _ in range(100):
        data.ctrl[:] = (3.0, -2.0, 1.0)
        mujoco.mj_step(model, data)
    mujoco.mj_forward(model, data)
    pose, twist, _th, rates = base_states(model, get_state(model, data)[None])
    np.testing.assert_allclose(pose[0], base_pose(model, data), atol=1e-12)
    np.testing.assert_allclose(twist[0], body_twist(model, data), atol=1e-12)
    np.testing.assert_allclose(rates[0], [data.joint(w).qvel[0] for w in
                                          ("wheel1", "wheel2", "wheel3")])


def test_relative_pose_starts_at_the_origin():
    start = np.array([1.0, 2.0, np.pi / 2])
    pose = np.array([start, [1.0, 3.0, np.pi / 2 + 0.1]])
    np.testing.assert_allclose(relative(pose, start), [[0, 0, 0], [1.0, 0.0, 0.1]],
                               atol=1e-12)


def test_coast_starts_at_the_driven_twist_with_the_motors_off():
    """After the ramped drive the platform moves at the commanded twist, and the motors
    are in torque mode (no velocity feedback) at zero torque; ``setup`` runs on the
    settled model. Tolerance: the instantaneous twist ripples within each roller pitch
    (the yaw-rate ripple of the roller study, about 4 %), so 5 % of each component's
    scale (0.3 m/s, 1 rad/s)."""
    seen = []
    model, data = coast_start((0.3, 0.0, 1.0), 1.0, lambda m: seen.append(m.opt.timestep))
    assert seen == [model.opt.timestep]
    error = np.abs(body_twist(model, data) - (0.3, 0.0, 1.0))
    assert np.all(error <= 0.05 * np.array([0.3, 0.3, 1.0])), error
    assert np.all(data.ctrl == 0.0)
    assert actuation_mode(model) is ActuationMode.TORQUE


@pytest.mark.parametrize("twist, drive_time, match", [
    ((0.3, 0.0), 1.0, "twist = "), ((0.3, np.nan, 0.0), 1.0, "twist = "),
    ((0.3, 0.0, 0.0), 0.0, r"drive_time = 0.0 s; valid range is \(0, 30\] s")])
def test_coast_start_refuses_bad_input(twist, drive_time, match):
    with pytest.raises(ValueError, match=match):
        coast_start(twist, drive_time)


def test_phase_lag_counts_steps_of_wheel_turn_with_its_sign():
    """Physics wheels turning 0.01 rad per step, the model 0.03 rad behind: −3 steps'
    turns; 0.02 rad ahead on one wheel only: +2; wheels standing still: 0."""
    t = np.arange(50)
    phys = np.column_stack([0.01 * t] * 3)

    def run(model):
        return SimpleNamespace(wheel_angles=phys, hybrid=SimpleNamespace(thetas=model))

    assert phase_lag_steps(run(phys - 0.03)) == pytest.approx(-3.0, rel=1e-9)
    ahead = phys.copy()
    ahead[:, 1] += 0.02
    assert phase_lag_steps(run(ahead)) == pytest.approx(2.0, rel=1e-9)
    still = np.zeros((50, 3))
    assert phase_lag_steps(SimpleNamespace(wheel_angles=still,
                                           hybrid=SimpleNamespace(thetas=still))) == 0.0
