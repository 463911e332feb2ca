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
