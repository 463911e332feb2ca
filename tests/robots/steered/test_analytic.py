"""Steered-class kinematics: (1,2) ICR geometry, (2,1) sleigh dynamics and mass data."""

import math

import numpy as np
import pytest

from wmr_mujoco.analytic.integrate import integrate
from wmr_mujoco.robots.single_steer.inertia import sleigh_inertia
from wmr_mujoco.robots.single_steer.params import SingleSteerParams
from wmr_mujoco.robots.steered import analytic as steered

A = 0.2


@pytest.mark.parametrize("b1,b2", [(0.3, -0.3), (0.5, 0.5), (1.0, -0.2), (-0.4, 0.7)])
def test_double_twist_moves_each_wheel_along_its_plane(b1, b2):
    # Rigid body: contact i moves at (u − r p_y, v + r p_x); it must be v_i (cos β_i, sin β_i).
    u, v, r = steered.double_twist(0.4, b1, b2, A)
    v2 = steered.double_rear_speed(0.4, b1, b2)
    for (px, beta, vi) in ((A, b1, 0.4), (-A, b2, v2)):
        assert np.array([u, v + r * px]) == pytest.approx(vi * np.array([math.cos(beta),
                                                                         math.sin(beta)]))


@pytest.mark.parametrize("b1,b2", [(0.3, -0.3), (1.0, -0.2), (-0.4, 0.7)])
def test_icr_of_the_twist_is_where_the_axles_meet(b1, b2):
    u, v, r = steered.double_twist(0.4, b1, b2, A)
    assert np.array([-v / r, u / r]) == pytest.approx(steered.axle_intersection(b1, b2, A))


def test_parallel_steering_translates():
    u, v, r = steered.double_twist(0.4, 0.5, 0.5, A)
    assert r == pytest.approx(0.0, abs=1e-15)
    assert (u, v) == pytest.approx((0.4 * math.cos(0.5), 0.4 * math.sin(0.5)))
    assert np.all(np.isinf(steered.axle_intersection(0.5, 0.5, A)))


def test_rear_wheel_across_the_body_is_a_clear_error():
    with pytest.raises(ValueError, match="beta_rear"):
        steered.double_rear_speed(0.4, 0.1, math.pi / 2)


def test_sleigh_yaw_rate_decays_exponentially():
    # Chaplygin sleigh, β = 0, c = (c_x, 0), constant v: ψ̈ = −(M v c_x / I) ψ̇ with
    # I = I_P + I_f, so ψ̇(t) = ψ̇₀ exp(−M v c_x t / I). RK4 at 2 ms: error O(Δt⁴).
    inertia = steered.SleighInertia(5.0, (0.15, 0.0), 0.25, 0.001)
    v, rate0 = 0.4, 0.3
    p0 = steered.single_momentum(rate0, v, 0.0, 0.0, inertia)
    states = integrate(lambda x, u: steered.single_rates(x, u, inertia),
                       np.array([0, 0, 0, 0, p0]), np.tile([v, 0.0], (1000, 1)), 0.002)
    rates = [steered.single_yaw_rate(s[4], v, 0.0, 0.0, inertia) for s in states]
    t = 0.002 * np.arange(1001)
    assert rates == pytest.approx(rate0 * np.exp(-5.0 * v * 0.15 * t / 0.251), rel=1e-8)


def test_steady_steering_gives_a_straight_crab():
    # With p = 0 and β, v constant the yaw rate is the one that keeps p = M v (c × e):
    # starting from rest-consistent momentum the robot translates along ψ + β.
    inertia = sleigh_inertia(SingleSteerParams())
    beta, v = 0.5, 0.4
    p0 = steered.single_momentum(0.0, v, beta, 0.0, inertia)
    states = integrate(lambda x, u: steered.single_rates(x, u, inertia),
                       np.array([0, 0, 0, beta, p0]), np.tile([v, 0.0], (500, 1)), 0.002)
    assert states[-1, 2] == pytest.approx(0.0, abs=1e-12)
    assert states[-1, :2] == pytest.approx(v * 1.0 * np.array([math.cos(beta), math.sin(beta)]))


def test_icr_lies_on_the_steered_axle_line():
    icr = steered.single_icr(0.4, 0.3, 0.5)
    axle = np.array([-math.sin(0.3), math.cos(0.3)])
    assert icr[0] * axle[1] - icr[1] * axle[0] == pytest.approx(0.0, abs=1e-15)
