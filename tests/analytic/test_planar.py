import numpy as np
import pytest

from wmr_mujoco.analytic.planar import (
    cumulative_path,
    path_length,
    twist_step,
    wrap_angle,
    yaw_from_rotation,
)


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


@pytest.mark.parametrize("twist", [(0.3, -0.1, 1.2), (0.0, 0.2, -0.7), (0.5, 0.1, 3e-6),
                                   (0.4, 0.0, 0.0)])
def test_twist_step_is_the_exact_flow_of_the_kinematic_model(twist, rk4):
    """Against RK4 with a thousandth of the step on ``(Ẋ, Ẏ, ψ̇) = (Rot(ψ)(u, v), r)``:
    RK4's error at h = 0.5 ms over 0.5 s is O(h⁴) ≈ 1e-14; 1e-12 for round-off. The small
    |θ| uses the series (error θ⁴/120 relative ≈ 1e-23 here)."""
    pose = np.array([0.2, -0.4, 0.9])

    def f(x):
        c, s = np.cos(x[2]), np.sin(x[2])
        return np.array([c * twist[0] - s * twist[1], s * twist[0] + c * twist[1], twist[2]])

    np.testing.assert_allclose(twist_step(pose, np.array(twist), 0.5),
                               rk4(f, pose, 5e-4, 1000), atol=1e-12)


def test_twist_steps_are_twist_step_after_twist_step():
    """All steps at once are the steps one by one (same arithmetic and order of sums).

    Twists with yaw rates in the series branch (|r Δt| < 1e-4) and outside it; the
    tolerance 1e-14 relative allows NumPy's and libm's sin/cos to differ in the last bit
    on some CPUs (on the reference machine they are equal, the poses bit for bit).
    """
    from wmr_mujoco.analytic.planar import twist_steps

    rng = np.random.default_rng(3)
    w = rng.normal(size=(2000, 3)) * [0.3, 0.2, 1.0]
    w[::3, 2] = 0.0
    w[1::5, 2] *= 1e-3
    x = np.array([0.2, -0.1, 0.4])
    ref = [x]
    for tw in w:
        x = twist_step(x, tw, 0.002)
        ref.append(x)
    np.testing.assert_allclose(twist_steps(ref[0], w, 0.002), ref, rtol=1e-14, atol=1e-14)


def test_twist_steps_of_a_constant_twist_close_the_circle():
    """u = 0.5 m/s, r = 1 rad/s for 2π s: back at the start, heading + 2π.

    Each step is the exact arc, so only round-off accumulates over 6283 steps (~1e-12).
    """
    from wmr_mujoco.analytic.planar import twist_steps

    n = 6283
    dt = 2 * np.pi / n
    out = twist_steps(np.zeros(3), np.tile([0.5, 0.0, 1.0], (n, 1)), dt)
    np.testing.assert_allclose(out[-1], [0.0, 0.0, 2 * np.pi], atol=1e-9)
    # Halfway round the circle of radius u / r = 0.5 m: at (0, 1).
    np.testing.assert_allclose(np.max(out[:, 1]), 1.0, atol=1e-6)
