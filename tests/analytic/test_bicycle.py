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


def _stepwise(q0, inputs, dt, ell, speed=None):
    from wmr_mujoco.analytic.integrate import rk4_states

    def rhs(q, u):
        v = u[0] if speed is None else speed(np.array([u[0]]), np.array([q[3]]))[0]
        return bicycle.rates(q, np.array([v, u[1]]), ell)
    return rk4_states(rhs, q0, inputs, dt)


def test_rk4_trajectory_is_rk4_step_bit_for_bit():
    # A steering ramp and hold, the speed changing every 100 steps, through a full turn
    # (cos ψ and sin ψ of every sign): each state is the step-by-step RK4's, to the bit.
    rng = np.random.default_rng(5)
    n, dt, ell = 3000, 2e-3, 0.9
    steer_rate = np.where(np.arange(n) < 400, 1.0, 0.0) * 0.6
    inputs = np.column_stack([np.repeat(rng.uniform(0.5, 2.0, n // 100), 100), steer_rate])
    q0 = np.array([0.2, -0.1, 2.5, 0.0])
    want = _stepwise(q0, inputs, dt, ell)
    np.testing.assert_array_equal(bicycle.rk4_trajectory(q0, inputs, dt, ell), want)
    # With a stage speed that reads φ (the tricycle's): the same.
    speed = lambda v, phi: v / (1.0 - 0.3 * np.tan(phi))  # noqa: E731
    np.testing.assert_array_equal(bicycle.rk4_trajectory(q0, inputs, dt, ell, speed),
                                  _stepwise(q0, inputs, dt, ell, speed))


def test_rk4_trajectory_declines_what_it_cannot_give():
    q0 = np.zeros(4)
    inputs = np.tile([1.0, 0.0], (10, 1))
    assert bicycle.rk4_trajectory(q0, np.array([[1.0, np.nan]]), 1e-3, 1.0) is None
    assert bicycle.rk4_trajectory(np.array([0, 0, 0, np.inf]), inputs, 1e-3, 1.0) is None
    assert bicycle.rk4_trajectory(q0, inputs, 1e-3, 1.0, lambda v, p: v * np.nan) is None
    assert bicycle.rk4_trajectory(q0, inputs[:, :1], 1e-3, 1.0) is None
