import math

import numpy as np
import pytest

from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok


def _random_layout(rng, n):
    return ok.WheelLayout(rng.uniform(-0.5, 0.5, (n, 2)), rng.uniform(-np.pi, np.pi, n),
                          rng.uniform(-1.0, 1.0, n), rng.uniform(0.02, 0.2, n))


@pytest.mark.parametrize("n", [3, 4, 5])
def test_inverse_for_arbitrary_geometry(rng, n):
    for _ in range(20):
        layout = _random_layout(rng, n)
        H = ok.wheel_jacobian(layout)
        if n == 3:
            np.testing.assert_allclose(H @ np.linalg.inv(H), np.eye(3), atol=1e-9)
        nu = rng.normal(size=3)
        np.testing.assert_allclose(ok.body_twist(layout, ok.wheel_rates(layout, nu)), nu,
                                   rtol=1e-9, atol=1e-9)


def test_general_form_reproduces_lecture_matrix():
    r, L = 0.05, 0.2
    s = np.sqrt(3) / 2
    lecture = np.array([[0, 1, L], [-s, -0.5, L], [s, -0.5, L]])  # slide, written out
    np.testing.assert_allclose(r * ok.wheel_jacobian(ok.symmetric_layout(r, L)), lecture,
                               atol=1e-15)
    np.testing.assert_allclose(ok.lecture_matrix(L), lecture)


def test_mecanum_from_the_same_function():
    """Lynch & Park eq. (13.10), rows FL, FR, RL, RR, columns (v_x, v_y, ω)."""
    r, a, b = 0.05, 0.3, 0.2
    expected = np.array([[1, -1, -(a + b)], [1, 1, a + b], [1, 1, -(a + b)],
                         [1, -1, a + b]]) / r
    np.testing.assert_allclose(ok.wheel_jacobian(ok.mecanum_layout(r, a, b)), expected,
                               atol=1e-12)


def test_body_world_round_trip(rng):
    for _ in range(10):
        psi, nu = rng.uniform(-4, 4), rng.normal(size=3)
        world = ok.body_to_world(psi, nu)
        assert np.hypot(*world[:2]) == pytest.approx(np.hypot(*nu[:2]))
        np.testing.assert_allclose(ok.world_to_body(psi, world), nu)
    np.testing.assert_allclose(ok.body_to_world(np.pi / 2, [1, 0, 0]), [0, 1, 0], atol=1e-15)


def test_roller_slide_speeds():
    layout = ok.symmetric_layout(0.05, 0.2)
    # Wheel 1 sits at (L, 0), rolling along +y: moving along +x is pure roller slide.
    slide = ok.roller_slide_speeds(layout, [1.0, 0.0, 0.0])
    assert slide[0] == pytest.approx(1.0)
    assert ok.wheel_rates(layout, [1.0, 0.0, 0.0])[0] == pytest.approx(0.0, abs=1e-13)
    # Pure rotation: contact points move tangentially, no roller slide.
    np.testing.assert_allclose(ok.roller_slide_speeds(layout, [0, 0, 2.0]), 0, atol=1e-15)


@pytest.mark.parametrize("kwargs, match", [
    ({"positions": np.zeros((2, 2))}, "at least 3"),
    ({"positions": np.zeros((3, 3))}, r"positions must have shape \(N, 2\)"),
    ({"radii": [0.1, -0.1, 0.1]}, "radii"),
    ({"roller_angles": [0, 0, np.pi / 2]}, "roller_angles"),
    ({"drive_angles": [0, np.nan, 0]}, "drive_angles contains non-finite"),
])
def test_layout_bad_input(kwargs, match):
    args = {"positions": np.eye(3)[:, :2], "drive_angles": [0, 1, 2],
            "roller_angles": [0, 0, 0], "radii": [0.1] * 3} | kwargs
    with pytest.raises(ValueError, match=match):
        ok.WheelLayout(**args)


def test_rank_deficient_layout_is_reported():
    layout = ok.WheelLayout(np.array([[0.0, 0.1], [0.0, -0.1], [0.0, 0.3]]), np.zeros(3),
                            np.zeros(3), np.full(3, 0.05))
    with pytest.raises(ValueError, match="rank < 3"):
        ok.body_twist(layout, np.zeros(3))
    with pytest.raises(ValueError, match=r"nu must have shape \(3,\)"):
        ok.wheel_rates(layout, [1.0, 2.0])


def test_mecanum_roller_slide_is_the_whole_relative_velocity():
    # Independent check: under the ideal rates the contact's velocity relative to the
    # rim, v_c − R θ̇ d_i, has no component along the roller axis (Lynch & Park's
    # condition), so its magnitude is what the roller takes up.
    lay = ok.mecanum_layout(0.05, 0.15, 0.12)
    nu = np.array([0.2, -0.1, 0.7])
    rates = ok.wheel_rates(lay, nu)
    for i, (x, y) in enumerate(lay.positions):
        v_c = np.array([nu[0] - nu[2] * y, nu[1] + nu[2] * x])
        d = np.array([np.cos(lay.drive_angles[i]), np.sin(lay.drive_angles[i])])
        rel = v_c - lay.radii[i] * rates[i] * d
        assert abs(ok.roller_slide_speeds(lay, nu)[i]) == pytest.approx(
            np.linalg.norm(rel), rel=1e-12)


@pytest.mark.parametrize("n", [3, 4, 5])
def test_slide_speeds_per_wheel_are_the_layouts_array_arithmetic(rng, n):
    # roller_slide_speeds works wheel by wheel in Python floats; the docstring's formula
    # on the (n,) arrays, −(−sin(β+γ) v_x + cos(β+γ) v_y + tan γ (cos(β+γ) v_x +
    # sin(β+γ) v_y)), must give the same floats (the validation's figures rest on it),
    # for twists over six decades and any layout.
    for _ in range(50):
        layout = _random_layout(rng, n)
        nu = rng.normal(size=3) * 10.0 ** rng.uniform(-4, 2)
        x, y = layout.positions.T
        vx, vy = nu[0] - nu[2] * y, nu[1] + nu[2] * x
        ang = layout.drive_angles + layout.roller_angles
        along = np.cos(ang) * vx + np.sin(ang) * vy
        across = -np.sin(ang) * vx + np.cos(ang) * vy
        want = -(across + np.tan(layout.roller_angles) * along)
        assert ok.roller_slide_speeds(layout, nu).tobytes() == want.tobytes()


def test_frame_turns_are_the_rotation_in_floats(rng):
    # world_to_body and body_to_world read the rates as Python floats: the same floats as
    # the rotation by math.cos and math.sin written here, and bad rates still named.
    for _ in range(100):
        psi, w = rng.uniform(-7, 7), rng.normal(size=3)
        c, s = math.cos(psi), math.sin(psi)
        assert ok.world_to_body(psi, w).tolist() == [c * w[0] + s * w[1],
                                                     -s * w[0] + c * w[1], w[2]]
        assert ok.body_to_world(psi, w).tolist() == [c * w[0] - s * w[1],
                                                     s * w[0] + c * w[1], w[2]]
    with pytest.raises(ValueError, match="world_rates contains non-finite"):
        ok.world_to_body(0.3, [1.0, np.nan, 0.0])
