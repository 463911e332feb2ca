import mujoco
import numpy as np
import pytest

from wmr_mujoco import load, set_actuation_mode
from wmr_mujoco.models.actuation import actuation_mode
from wmr_mujoco.robots.disc.params import DiscParams
from wmr_mujoco.sim.stepping import rollout

from conftest import ACTUATED, model_differences


@pytest.mark.parametrize("robot", ACTUATED)
def test_round_trip_restores_rate_mode(robot):
    model = load(robot)
    assert actuation_mode(model) == "rate"
    set_actuation_mode(model, "torque")
    assert actuation_mode(model) == "torque"
    np.testing.assert_array_equal(model.actuator_ctrlrange, model.actuator_forcerange)
    set_actuation_mode(model, "rate")
    assert model_differences(model, load(robot)) == []


def test_torque_mode_drives_disc_at_rolling_acceleration():
    """Constant wheel torque τ on the mounted disc, rolling without slip.

    Moving mass M = disc + carriage, wheel inertia J = m R²/2:
    a = τ R / (J + M R²). The contact is soft (penetration ~5 µm, creep of the friction
    constraint), so a is expected within 1e-3 of the rigid value.
    """
    p = DiscParams()
    model = load("disc")
    set_actuation_mode(model, "torque")
    data = mujoco.MjData(model)
    tau = 0.4
    rollout(model, data, 0.2, lambda t: np.array([tau, 0.0]))  # settle into steady rolling
    v0, t0 = data.qvel[0], data.time
    rollout(model, data, 1.0, lambda t: np.array([tau, 0.0]))
    measured = (data.qvel[0] - v0) / (data.time - t0)
    r = p.wheel.radius
    expected = tau * r / (0.5 * p.wheel.mass * r**2 + (p.wheel.mass + p.mount_mass) * r**2)
    assert measured == pytest.approx(expected, rel=1e-3)


def test_rate_mode_tracks_wheel_rate():
    model = load("disc")
    data = mujoco.MjData(model)
    rollout(model, data, 1.0, lambda t: np.array([5.0, 0.0]))
    assert data.qvel[4] == pytest.approx(5.0, rel=1e-4)


def test_bad_mode_is_clear():
    with pytest.raises(ValueError, match="unknown actuation mode 'current'.*rate, torque"):
        set_actuation_mode(load("disc"), "current")


def test_model_without_actuators_is_clear():
    with pytest.raises(ValueError, match="no actuators"):
        set_actuation_mode(load("disc_free"), "torque")
