"""Pose and twist read from a MuJoCo state, against rigid-body kinematics written here."""

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.validation.adapters import base_pose, body_pose, body_twist

XML = """
<mujoco>
  <option gravity="0 0 0"/>
  <worldbody>
    <body name="chassis">
      <freejoint/>
      <geom type="box" size="0.2 0.1 0.05" mass="1"/>
      <site name="base" pos="0.1 0.05 0"/>
    </body>
  </worldbody>
</mujoco>
"""


def _state(yaw: float, vel_world: np.ndarray, yaw_rate: float):
    model = mujoco.MjModel.from_xml_string(XML)
    data = mujoco.MjData(model)
    data.qpos[:3] = (1.0, -2.0, 0.3)
    data.qpos[3:7] = (math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2))
    data.qvel[:3] = vel_world          # free joint: world-frame linear velocity of the body
    data.qvel[3:6] = (0.0, 0.0, yaw_rate)  # and body-frame angular velocity
    mujoco.mj_forward(model, data)
    return model, data


@pytest.mark.parametrize("yaw", [0.0, 0.7, -2.9, math.pi - 1e-9])
def test_poses_of_body_and_site(yaw):
    model, data = _state(yaw, np.zeros(3), 0.0)
    np.testing.assert_allclose(body_pose(model, data, model.body("chassis").id),
                               [1.0, -2.0, yaw], atol=1e-12)
    c, s = math.cos(yaw), math.sin(yaw)
    site = np.array([1.0 + 0.1 * c - 0.05 * s, -2.0 + 0.1 * s + 0.05 * c, yaw])
    np.testing.assert_allclose(base_pose(model, data), site, atol=1e-12)


def test_twist_is_the_site_velocity_in_the_body_frame():
    """``(u, v) = Rᵀ (V + r ẑ × R p)``, ``r`` the yaw rate, for the site at body offset p."""
    yaw, vel, rate = 0.9, np.array([0.4, -0.3, 0.0]), 1.5
    model, data = _state(yaw, vel, rate)
    c, s = math.cos(yaw), math.sin(yaw)
    rot = np.array([[c, -s], [s, c]])
    arm = rot @ np.array([0.1, 0.05])
    world = vel[:2] + rate * np.array([-arm[1], arm[0]])
    np.testing.assert_allclose(body_twist(model, data), [*(rot.T @ world), rate], atol=1e-12)


def test_per_distinct_row_calls_once_per_row_in_first_appearance_order():
    from wmr_mujoco.validation.adapters import per_distinct_row

    rows = np.array([[1.0, 2.0], [0.0, 1.0], [1.0, 2.0], [-0.0, 1.0], [0.0, 1.0]])
    calls = []

    def fn(r):
        calls.append(r.tolist())
        return [r[0] + r[1], np.copysign(1.0, r[0])]

    got = per_distinct_row(fn, rows, 2)
    np.testing.assert_array_equal(got, [[3, 1], [1, 1], [3, 1], [1, -1], [1, 1]])
    assert calls == [[1.0, 2.0], [0.0, 1.0], [-0.0, 1.0]]  # -0.0 is its own row
    assert per_distinct_row(fn, np.empty((0, 2)), 2).shape == (0, 2)


@pytest.mark.parametrize("robot, name", [("omni3", "translate+rotate"),
                                         ("omni3", "square with rotation"),
                                         ("mecanum4", "rotate (ramp)")])
def test_controls_on_are_the_controls_of_each_step(robot, name):
    from wmr_mujoco import load
    from wmr_mujoco.robots import get_spec
    from wmr_mujoco.validation.runner import make_adapter

    spec = get_spec(robot)
    s = next(x for x in spec.scenarios if x.name == name).members(0, 1)[0]
    model = load(robot)
    adapter = make_adapter(spec, s, model)
    inputs = s.inputs_on(3000, model.opt.timestep)
    states = adapter.trajectory(np.zeros(len(adapter.state_names)), inputs,
                                model.opt.timestep)
    want = [adapter.controls(u, x) for u, x in zip(inputs, states, strict=False)]
    np.testing.assert_array_equal(adapter.controls_on(inputs, states[:-1]), want)


def test_base_site_is_each_models_own():
    # The site id is remembered for the last model read: a model whose ``base`` site has
    # another id (a site before it), read in turn with the first, gets its own site's pose;
    # a model without a ``base`` site is named by MuJoCo's KeyError.
    other = mujoco.MjModel.from_xml_string(XML.replace(
        '<site name="base"', '<site name="mark" pos="-0.1 0 0"/>\n      <site name="base"'))
    assert other.site("base").id != mujoco.MjModel.from_xml_string(XML).site("base").id
    model, data = _state(0.4, np.zeros(3), 0.0)
    other_data = mujoco.MjData(other)
    mujoco.mj_forward(other, other_data)
    for _ in range(2):
        np.testing.assert_array_equal(base_pose(model, data)[:2],
                                      data.site_xpos[model.site("base").id][:2])
        np.testing.assert_array_equal(base_pose(other, other_data)[:2],
                                      other_data.site_xpos[other.site("base").id][:2])
    bare = mujoco.MjModel.from_xml_string(XML.replace('<site name="base"', '<site name="b"'))
    with pytest.raises(KeyError, match="base"):
        base_pose(bare, mujoco.MjData(bare))
