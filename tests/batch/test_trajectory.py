"""BatchTrajectory: member first, each member a wmr.Trajectory."""

import numpy as np
import pytest

from wmr_mujoco.api import Trajectory
from wmr_mujoco.batch.trajectory import BatchTrajectory


def _batch() -> BatchTrajectory:
    states = np.arange(2 * 4 * 3, dtype=float).reshape(2, 4, 3)
    return BatchTrajectory(np.arange(4) * 0.1, states, np.zeros((2, 3, 2)),
                           ("x", "y", "heading"), ("m", "m", "rad"), "rollout")


def test_components_and_pose_are_member_first():
    b = _batch()
    assert len(b) == 2 and b.pose.shape == (2, 4, 3)
    np.testing.assert_array_equal(b["y"], b.states[:, :, 1])
    with pytest.raises(KeyError, match="the components are x, y, heading"):
        b["speed"]


def test_member_is_a_trajectory():
    b = _batch()
    m = b.member(1)
    assert isinstance(m, Trajectory)
    np.testing.assert_array_equal(m.pose, b.states[1])
    np.testing.assert_array_equal(b.member(-1).states, m.states)
    with pytest.raises(IndexError, match="valid members are 0..1"):
        b.member(2)


def test_a_velocity_state_is_not_a_pose():
    b = BatchTrajectory(np.zeros(2), np.zeros((1, 2, 2)), np.zeros((1, 1, 2)), ("u", "r"),
                        ("m/s", "rad/s"), "warp")
    with pytest.raises(ValueError, match="is not a planar pose"):
        _ = b.pose
