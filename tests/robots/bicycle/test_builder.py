"""The planar bicycle's geometry: wheelbase, steering axis and rest on the floor."""

import dataclasses

import mujoco
import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.robots.bicycle.params import BicycleParams


@pytest.mark.parametrize("wheelbase", [1.05, 0.8])
def test_wheel_centres_one_wheelbase_apart_and_steer_axis_through_the_front(wheelbase):
    p = dataclasses.replace(BicycleParams(), wheelbase=wheelbase)
    model = load("bicycle", p)
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    rear, front = data.xpos[model.body("rear_wheel").id], data.xpos[model.body("front_wheel").id]
    assert front[0] - rear[0] == pytest.approx(wheelbase, abs=1e-12)
    assert rear[2] == pytest.approx(p.rear_wheel.radius) and \
        front[2] == pytest.approx(p.front_wheel.radius)
    steer = model.joint("steer")
    np.testing.assert_allclose(data.xanchor[steer.id][:2], front[:2], atol=1e-12)
    np.testing.assert_allclose(data.xaxis[steer.id], [0, 0, 1], atol=1e-12)


def test_weight_rests_on_the_two_wheels():
    """Settled under gravity: the floor carries m g through the two wheel contacts only.

    Tolerance: 1 % of the weight, for the contact's own residual acceleration after 1 s
    of settling (the contact damping time constant is a few ms).
    """
    model = load("bicycle")
    data = mujoco.MjData(model)
    mujoco.mj_resetData(model, data)
    for _ in range(int(1.0 / model.opt.timestep)):
        mujoco.mj_step(model, data)
    wheels = {model.body("rear_wheel").id, model.body("front_wheel").id}
    force, total = np.zeros(6), 0.0
    for i, con in enumerate(data.contact[:data.ncon]):
        bodies = {model.geom_bodyid[con.geom1], model.geom_bodyid[con.geom2]}
        assert bodies & wheels, "only the wheels touch the floor"
        mujoco.mj_contactForce(model, data, i, force)
        total += force[0]
    weight = float(np.sum(model.body_mass)) * -model.opt.gravity[2]
    assert total == pytest.approx(weight, rel=0.01)
