"""Unicycle, bicycle and tricycle kinematics: ICR geometry checked as rigid-body motion."""

import numpy as np
import pytest

from wmr_mujoco.analytic import bicycle, tricycle, unicycle


def _point_velocity(q, qdot, offset_body):
    """Velocity of a point fixed at ``offset_body`` in the body frame of heading q[2]."""
    c, s = np.cos(q[2]), np.sin(q[2])
    r = np.array([c * offset_body[0] - s * offset_body[1], s * offset_body[0] + c * offset_body[1]])
    return qdot[:2] + qdot[2] * np.array([-r[1], r[0]])


@pytest.mark.parametrize("phi", [0.3, -0.5, 1.0])
def test_bicycle_icr_is_at_rest(phi):
    ell, v = 1.2, 2.0
    q = np.array([0.5, -0.3, 0.7, phi])
    qdot = bicycle.rates(q, [v, 0.0], ell)
    icr = (0.0, bicycle.icr_radius(phi, ell))
    np.testing.assert_allclose(_point_velocity(q, qdot, icr), 0.0, atol=1e-12)
    # Front contact moves along the front wheel plane at v_f = v / cos φ.
    vf = _point_velocity(q, qdot, (ell, 0.0))
    assert np.hypot(*vf) == pytest.approx(v / np.cos(phi))
    assert np.arctan2(vf[1], vf[0]) == pytest.approx(q[2] + phi)
    assert bicycle.front_speed_to_rear(v / np.cos(phi), phi) == pytest.approx(v)


@pytest.mark.parametrize("phi", [0.4, -0.2])
def test_tricycle_rear_wheels_roll_about_the_icr(phi):
    ell, w, v = 0.5, 0.4, 1.0
    q = np.array([0.0, 0.0, 0.3, phi])
    qdot = tricycle.rates(q, [v, 0.0], ell)
    vl, vr = tricycle.rear_wheel_speeds(v, phi, w, ell)
    assert np.hypot(*_point_velocity(q, qdot, (0.0, w / 2))) == pytest.approx(abs(vl))
    assert np.hypot(*_point_velocity(q, qdot, (0.0, -w / 2))) == pytest.approx(abs(vr))
    assert tricycle.midpoint_speed_from_left(vl, phi, w, ell) == pytest.approx(v)
    assert sum(tricycle.differential_speeds(v, phi, w, ell)) / 2 == pytest.approx(v)
    assert tricycle.front_wheel_speed(v, phi) == pytest.approx(
        np.hypot(*_point_velocity(q, qdot, (ell, 0.0))))


def test_driven_wheel_on_the_icr_is_an_error():
    ell, w = 0.5, 0.4
    phi = np.arctan(2 * ell / w)
    with pytest.raises(ValueError, match="ICR on the driven left wheel"):
        tricycle.midpoint_speed_from_left(1.0, phi, w, ell)


def test_unicycle_straight_line():
    np.testing.assert_allclose(unicycle.constant_input_pose([0, 0, 0.5], 2.0, 0.0, 1.5)[0],
                               [3 * np.cos(0.5), 3 * np.sin(0.5), 0.5])
    assert bicycle.icr_radius(0.0, 1.0) == float("inf")
