"""The planar bicycle (lecture §2): ICR, wheel-plane constraints, input fields."""

import numpy as np
import pytest

from wmr_mujoco.analytic import bicycle


@pytest.mark.parametrize("phi", [0.3, -0.5, 1.0])
def test_bicycle_icr_is_at_rest(phi, point_velocity):
    ell, v = 1.2, 2.0
    q = np.array([0.5, -0.3, 0.7, phi])
    qdot = bicycle.rates(q, [v, 0.0], ell)
    icr = (0.0, bicycle.icr_radius(phi, ell))
    np.testing.assert_allclose(point_velocity(q, qdot, icr), 0.0, atol=1e-12)
    # Front contact moves along the front wheel plane at v_f = v / cos φ.
    vf = point_velocity(q, qdot, (ell, 0.0))
    assert np.hypot(*vf) == pytest.approx(v / np.cos(phi))
    assert np.arctan2(vf[1], vf[0]) == pytest.approx(q[2] + phi)
    assert bicycle.front_speed_to_rear(v / np.cos(phi), phi) == pytest.approx(v)


@pytest.mark.parametrize("phi", [0.0, 0.4, -0.9])
def test_both_wheels_roll_without_side_slip(phi, point_velocity):
    """Pfaffian rows of the rear (heading ψ) and front (ψ + φ) wheel planes vanish."""
    ell = 0.9
    q = np.array([0.2, 0.1, -1.1, phi])
    qdot = bicycle.rates(q, [1.3, 0.2], ell)
    for offset, heading in (((0.0, 0.0), q[2]), ((ell, 0.0), q[2] + q[3])):
        vel = point_velocity(q, qdot, offset)
        assert vel[0] * np.sin(heading) - vel[1] * np.cos(heading) == pytest.approx(
            0.0, abs=1e-12)
    np.testing.assert_allclose(bicycle.input_fields(q, ell) @ np.array([1.3, 0.2]), qdot,
                               atol=1e-15)


def test_straight_ahead_has_no_icr():
    assert bicycle.icr_radius(0.0, 1.0) == float("inf")


@pytest.mark.parametrize("ell", [0.0, -1.0, float("nan")])
def test_bad_wheelbase_is_refused(ell):
    with pytest.raises(ValueError, match="wheelbase"):
        bicycle.rates([0, 0, 0, 0.1], [1.0, 0.0], ell)
