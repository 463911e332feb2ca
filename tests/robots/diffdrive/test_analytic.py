"""Differential-drive kinematics against the unicycle and the tricycle's constraints."""

import numpy as np
import pytest

from wmr_mujoco.analytic import constraints, unicycle
from wmr_mujoco.analytic.integrate import integrate
from wmr_mujoco.robots.diffdrive import analytic as diffdrive

B, R = 0.36, 0.08


def test_twist_and_wheel_speeds_are_inverse():
    v, w = diffdrive.twist(0.41, 0.59, B)
    assert (v, w) == pytest.approx((0.5, 0.5))  # (0.41 + 0.59)/2, 0.18/0.36
    assert diffdrive.wheel_speeds(v, w, B) == pytest.approx((0.41, 0.59))


def test_constant_wheel_speeds_trace_the_unicycle_circle():
    # v = 0.5, ω = 0.5: the closed-form circle of radius 1 m; RK4 at 2 ms is exact to
    # O(Δt⁴) ≈ 1e-11 m (analytic/integrate.py), so 1e-9 m is a safe bound.
    t = 0.002 * np.arange(2001)
    states = integrate(lambda q, u: diffdrive.rates(q, u, B), np.zeros(3),
                       np.tile([0.41, 0.59], (2000, 1)), 0.002)
    exact = unicycle.constant_input_pose(np.zeros(3), 0.5, 0.5, t)
    assert np.abs(states - exact).max() < 1e-9


def test_unequal_radii_turn_at_equal_rates():
    # θ̇ = 10 rad/s, R_L = 0.08, R_R = 0.081: v = 10·0.0805, ω = 10·0.001/0.36.
    v, w = diffdrive.twist_from_rates(10.0, 10.0, B, 0.08, 0.081)
    assert (v, w) == pytest.approx((0.805, 0.01 / 0.36))


def test_icr_on_the_axle():
    assert diffdrive.icr_offset(0.5, 0.5) == pytest.approx(1.0)
    assert diffdrive.icr_offset(0.5, 0.0) == np.inf


def test_pfaffian_annihilates_rolling_motion():
    rng = np.random.default_rng(1)
    for _ in range(5):
        psi, v, w = rng.uniform(-3, 3, 3)
        vl, vr = diffdrive.wheel_speeds(v, w, B)
        qdot = np.array([v * np.cos(psi), v * np.sin(psi), w, vl / R, vr / R])
        q = np.array([0.0, 0.0, psi, 0.0, 0.0])
        assert diffdrive.pfaffian(q, B, R, R) @ qdot == pytest.approx(np.zeros(3), abs=1e-12)


def test_pfaffian_is_the_tricycle_rear_axle():
    # The tricycle's rear lateral and rear rolling rows (written independently in
    # constraints.py) without the steer and front-wheel columns.
    q = np.array([0.1, -0.2, 0.7, 0.0, 0.0])
    tri = constraints.tricycle(np.array([0.1, -0.2, 0.7, 0.0, 0.0, 0.0, 0.0]), 0.5, B, R, R)
    expected = tri[[0, 2, 3]][:, [0, 1, 2, 4, 5]]
    assert diffdrive.pfaffian(q, B, R, R) == pytest.approx(expected)


@pytest.mark.parametrize("bad", [0.0, -0.1, float("nan")])
def test_bad_track_is_a_clear_error(bad):
    with pytest.raises(ValueError, match="track"):
        diffdrive.twist(0.1, 0.2, bad)
