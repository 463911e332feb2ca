"""The unicycle (lecture §1): constraint, input fields and the closed-form pose."""

import numpy as np
import pytest

from wmr_mujoco.analytic import unicycle


@pytest.mark.parametrize("q, u", [((0.1, -0.2, 0.7), (1.5, 0.3)), ((2.0, 1.0, -2.5), (-0.4, 1.2))])
def test_rates_roll_without_side_slip(q, u):
    qd = unicycle.rates(q, u)
    # ẋ sin φ − ẏ cos φ = 0: no velocity across the wheel plane (exact up to round-off).
    assert qd[0] * np.sin(q[2]) - qd[1] * np.cos(q[2]) == pytest.approx(0.0, abs=1e-15)
    assert np.hypot(qd[0], qd[1]) == pytest.approx(abs(u[0]))
    np.testing.assert_allclose(unicycle.input_fields(q) @ np.asarray(u), qd, atol=1e-15)


@pytest.mark.parametrize("omega", [0.0, 0.8, -1.7])
def test_closed_form_pose_matches_integrated_rates(omega, rk4):
    """The closed form against an RK4 integration of ``q̇ = rates(q, u)``.

    Tolerance: RK4's global error ``O(Δt⁴)`` with Δt = 1 ms over 2 s and rates of order 1
    is below 1e-12; 1e-9 leaves room for round-off over 2000 steps.
    """
    q0, v, t = np.array([0.3, -0.1, 0.4]), 1.2, 2.0
    end = rk4(lambda q: unicycle.rates(q, [v, omega]), q0, 1e-3, 2000)
    np.testing.assert_allclose(unicycle.constant_input_pose(q0, v, omega, t)[0], end,
                               atol=1e-9)


def test_straight_line_pose():
    np.testing.assert_allclose(unicycle.constant_input_pose([0, 0, 0.5], 2.0, 0.0, 1.5)[0],
                               [3 * np.cos(0.5), 3 * np.sin(0.5), 0.5])


@pytest.mark.parametrize("q, u, name", [((0.0, 0.0), (1.0, 0.0), "q"),
                                        ((0.0, 0.0, 0.0), (np.nan, 0.0), "u")])
def test_bad_input_names_the_argument(q, u, name):
    with pytest.raises(ValueError, match=f"^{name} "):
        unicycle.rates(q, u)
