import numpy as np
import pytest

from wmr_mujoco.analytic.planar import cumulative_path, path_length, wrap_angle, yaw_from_rotation


def test_wrap_angle_into_half_open_interval():
    assert wrap_angle(3 * np.pi / 2) == pytest.approx(-np.pi / 2)
    assert wrap_angle(-0.1) == pytest.approx(-0.1)
    np.testing.assert_allclose(wrap_angle(np.array([2 * np.pi + 0.2, -2 * np.pi - 0.2])),
                               [0.2, -0.2])


def test_path_length_of_a_square_and_its_running_total():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]], float)
    assert path_length(square) == pytest.approx(4.0)
    np.testing.assert_allclose(cumulative_path(square), [0, 1, 2, 3, 4])
    assert path_length(square[:1]) == 0.0


@pytest.mark.parametrize("yaw", [-3.0, -0.5, 0.0, 1.2, 3.1])
def test_yaw_of_a_tilted_rotation(yaw):
    """R = Rz(ψ) Ry(θ) Rx(φ): the tilt does not change the heading read back."""
    def rz(a):
        return np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])

    def ry(a):
        return np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])

    def rx(a):
        return np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])

    rot = rz(yaw) @ ry(0.3) @ rx(-0.4)
    assert yaw_from_rotation(rot.ravel()) == pytest.approx(yaw, abs=1e-12)
