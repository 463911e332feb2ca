import math

import numpy as np
import pytest

from wmr_mujoco.envs.paths import DS, hermite_path, random_path


@pytest.mark.parametrize("seed", range(5))
def test_random_path_respects_its_curvature_bound(seed):
    start = np.array([0.3, -0.2, 0.7])
    path = random_path(np.random.default_rng(seed), start, length=4.0, max_curvature=1.5)
    np.testing.assert_allclose(path.points[0], start[:2])
    assert path.heading[0] == pytest.approx(start[2])
    # κ = dψ/ds from the polyline's heading; the trapezoid integration of κ(s) is exact
    # to O(ds²), so the bound holds to a small fraction of it.
    kappa = np.diff(path.heading[: path.end_index + 1]) / DS
    assert np.abs(kappa).max() <= 1.5 * (1 + 1e-3)
    # Vertices are one ds apart (arc length ≈ chord for |κ| ds ≪ 1).
    assert path.length == pytest.approx(4.0, rel=1e-3)


def test_random_path_is_seeded():
    a = random_path(np.random.default_rng(3), np.zeros(3), 2.0, 1.0)
    b = random_path(np.random.default_rng(3), np.zeros(3), 2.0, 1.0)
    np.testing.assert_array_equal(a.points, b.points)


def test_random_path_rejects_bad_sizes():
    with pytest.raises(ValueError, match="length"):
        random_path(np.random.default_rng(0), np.zeros(3), -1.0, 1.0)


def test_hermite_path_joins_the_two_poses():
    start, goal = np.array([0.0, 0.0, 0.0]), np.array([2.0, 1.0, math.pi / 2])
    path = hermite_path(start, goal, run_out=0.5)
    np.testing.assert_allclose(path.end_pose[:2], goal[:2], atol=1e-9)
    # Heading from finite differences of vertices DS apart: error O(κ DS) ≈ 0.02 rad.
    assert path.heading[path.end_index - 1] == pytest.approx(goal[2], abs=0.05)
    # The run-out continues straight along the goal heading.
    np.testing.assert_allclose(path.points[-1], goal[:2] + np.array([0.0, 0.5]), atol=DS)


def test_projection_cross_track_sign_on_a_straight_path():
    path = hermite_path(np.zeros(3), np.array([3.0, 0.0, 0.0]))
    left = path.project(np.array([1.0, 0.2]))
    right = path.project(np.array([1.0, -0.3]))
    assert left.cross_track == pytest.approx(0.2, abs=1e-9)
    assert right.cross_track == pytest.approx(-0.3, abs=1e-9)
    # The nearest vertex is within half a spacing of the foot of the perpendicular.
    assert left.s == pytest.approx(1.0, abs=DS / 2 + 1e-9)
