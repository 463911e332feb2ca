"""omni3's dynamic runs: state extraction against MuJoCo's own functions."""

import mujoco
import numpy as np

from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.robots.omni3.runs import base_states, relative, settled
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
