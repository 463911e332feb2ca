"""Closed loops on both backends: the physics tracks as its kinematic model does."""

from __future__ import annotations

import numpy as np
import pytest

from wmr_mujoco.control import closed_loop as cl
from wmr_mujoco.control.paths import make_path
from wmr_mujoco.robots import get_spec
from wmr_mujoco.validation.metrics import POSITION_PCT


@pytest.mark.parametrize(("robot", "controller", "path"), [
    ("diffdrive", "pure_pursuit", "circle"),
    ("bicycle", "stanley", "lane_change"),
    ("omni3", "holonomic", "figure_eight"),
])
def test_physics_tracks_like_the_model(robot, controller, path):
    """Start 0.1 m and 0.1 rad off the path. Open loop, the robot's validated target keeps
    the physics within POSITION_PCT % of the distance travelled of its kinematic model
    (0.5 % diffdrive and bicycle, 1 % omni3); closing the loop only corrects errors, so
    the two runs stay that close all along, and both correct the start offset: in the
    second half the physics' cross-track error is within the same allowance of the
    model's."""
    c = cl.compare(robot, controller, path, offset=(0.0, 0.1, 0.1))
    travelled = cl.duration_of(c.model) * 0.5
    allowance = get_spec(robot).targets[POSITION_PCT].value / 100 * travelled
    assert c.max_deviation <= allowance
    assert c.physics.worst_cross_track >= 0.09  # the start offset is seen
    assert c.physics.settled_cross_track <= c.model.settled_cross_track + allowance
    assert c.physics.final_position_error <= c.model.final_position_error + allowance


def test_go_to_pose_reaches_the_end_of_the_line():
    """Go-to-pose to the end of the 10 m line: in physics within the robot's 0.5 % of the
    10 m travelled (5 cm) of the goal, the model within 1 mm (its linear rate k_ρ = 1 1/s
    leaves e^-10 of the last metres)."""
    c = cl.compare("diffdrive", "go_to_pose", "line", offset=(0.0, 0.1, 0.0))
    assert c.model.final_position_error < 1e-3
    assert c.physics.final_position_error < 0.005 * 10.0


def test_start_pose_in_the_path_frame():
    """An offset (along, lateral, heading) = (1, 0.5, 0.1) on the circle's start (heading
    +x at the origin) lands at (1, 0.5, 0.1)."""
    p = make_path("circle")
    np.testing.assert_allclose(cl.start_pose(p, (1.0, 0.5, 0.1)), [1.0, 0.5, 0.1],
                               atol=1e-12)


def test_bad_input_before_any_run():
    with pytest.raises(ValueError, match="valid controllers"):
        cl.compare("diffdrive", "mpc", "line")
    with pytest.raises(ValueError, match="valid paths"):
        cl.compare("diffdrive", "pure_pursuit", "spiral")
    with pytest.raises(ValueError, match="drives"):
        cl.compare("omni3", "pure_pursuit", "line")
    with pytest.raises(ValueError, match="draws"):
        cl.family("diffdrive", "pure_pursuit", "line", draws=0)
