"""The tricycle (lecture §3): all three wheels about one ICR, the differential."""

import numpy as np
import pytest

from wmr_mujoco.robots.tricycle import analytic as tricycle


@pytest.mark.parametrize("phi", [0.4, -0.2])
def test_tricycle_rear_wheels_roll_about_the_icr(phi, point_velocity):
    ell, w, v = 0.5, 0.4, 1.0
    q = np.array([0.0, 0.0, 0.3, phi])
    qdot = tricycle.rates(q, [v, 0.0], ell)
    vl, vr = tricycle.rear_wheel_speeds(v, phi, w, ell)
    assert np.hypot(*point_velocity(q, qdot, (0.0, w / 2))) == pytest.approx(abs(vl))
    assert np.hypot(*point_velocity(q, qdot, (0.0, -w / 2))) == pytest.approx(abs(vr))
    assert tricycle.midpoint_speed_from_left(vl, phi, w, ell) == pytest.approx(v)
    assert sum(tricycle.differential_speeds(v, phi, w, ell)) / 2 == pytest.approx(v)
    assert tricycle.front_wheel_speed(v, phi) == pytest.approx(
        np.hypot(*point_velocity(q, qdot, (ell, 0.0))))
    np.testing.assert_allclose(point_velocity(q, qdot, (0.0, tricycle.icr_radius(phi, ell))),
                               0.0, atol=1e-12)


def test_driven_wheel_on_the_icr_is_an_error():
    ell, w = 0.5, 0.4
    phi = np.arctan(2 * ell / w)
    with pytest.raises(ValueError, match="ICR on the driven left wheel"):
        tricycle.midpoint_speed_from_left(1.0, phi, w, ell)


@pytest.mark.parametrize("track", [0.0, -0.3])
def test_bad_track_is_refused(track):
    with pytest.raises(ValueError, match="track"):
        tricycle.rear_wheel_speeds(1.0, 0.2, track, 0.5)


def test_midpoint_speeds_are_the_scalar_ones():
    import numpy as np

    from wmr_mujoco.robots.tricycle.analytic import midpoint_speed_from_left, midpoint_speeds

    steer = np.linspace(-0.9, 0.9, 41)
    v_left = np.linspace(0.2, 1.5, 41)
    want = [midpoint_speed_from_left(v, s, 0.4, 0.6) for v, s in
            zip(v_left, steer, strict=True)]
    np.testing.assert_array_equal(midpoint_speeds(v_left, steer, 0.4, 0.6), want)
    # The ICR on the driven wheel (tan φ = 2ℓ/w): NaN, where the scalar one raises.
    on_wheel = np.arctan(2 * 0.6 / 0.4)
    assert np.isnan(midpoint_speeds(np.array([1.0]), np.array([on_wheel]), 0.4, 0.6)[0])
