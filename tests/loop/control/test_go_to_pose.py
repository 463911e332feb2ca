"""Go-to-pose (Astolfi / Siegwart §3.6.2.4) closing the loop on the unicycle model."""

from __future__ import annotations

import math

import numpy as np
import pytest

from wmr_mujoco.loop.control.go_to_pose import GoToPose


@pytest.mark.parametrize("gains", [(0.0, 6.0, -5.0), (1.0, 6.0, 0.5), (1.0, 0.5, -5.0)])
def test_gains_outside_astolfi_conditions_are_refused(gains):
    with pytest.raises(ValueError, match="k_alpha - k_rho > 0"):
        GoToPose(*gains)


def test_linearisation_matches_polar_closed_loop():
    """The stated linear matrix against a numerical Jacobian of the polar closed loop
    ρ̇ = −k_ρ ρ cos α, α̇ = k_ρ sin α − k_α α − k_β β, β̇ = −k_ρ sin α (central differences,
    error O(h²) = 1e-12)."""
    c = GoToPose()

    def f(x):
        rho, a, b = x
        return np.array([-c.k_rho * rho * math.cos(a),
                         c.k_rho * math.sin(a) - c.k_alpha * a - c.k_beta * b,
                         -c.k_rho * math.sin(a)])
    h = 1e-6
    jac = np.stack([(f(h * e) - f(-h * e)) / (2 * h) for e in np.eye(3)], 1)
    np.testing.assert_allclose(c.linear_matrix(), jac, atol=1e-8)


def test_converges_from_seeded_starts(loop):
    """20 seeded starts 0.5-2 m away, any heading, goal anywhere: the pose reaches the goal.
    The slowest linear mode (ρ, at k_ρ = 1 1/s) leaves e^-16 of 2 m after the first
    ≤ 4 s saturated at 0.5 m/s: 2e-3 m and rad hold with margin for the nonlinear start."""
    rng = np.random.default_rng(0)
    c = GoToPose()
    for _ in range(20):
        goal = rng.uniform([-1, -1, -np.pi], [1, 1, np.pi])
        r, b = rng.uniform(0.5, 2.0), rng.uniform(-np.pi, np.pi)
        start = [goal[0] + r * np.cos(b), goal[1] + r * np.sin(b), rng.uniform(-np.pi, np.pi)]
        _, poses, _ = loop(c, goal, start, 20.0, 0.01)
        assert np.hypot(*(poses[-1, :2] - goal[:2])) < 2e-3
        assert abs(math.remainder(poses[-1, 2] - goal[2], 2 * math.pi)) < 2e-3


def test_late_convergence_rates_are_the_linear_modes(loop, rate):
    """Near the goal the distance decays at k_ρ and the heading error at the slower root
    of s² + (k_α − k_ρ) s − k_ρ k_β = 0 (for 1, 6, −5: (−5 + √5)/2 = −1.382 1/s). Rates
    fitted over 4-10 s (the fast root −3.62 1/s has faded by e^{-2.2·4} against the slow
    one) are within 2 % (the zero-order hold over 10 ms shifts them by O(Δt · 4) < 1 %)."""
    c = GoToPose(max_speed=10.0, max_rate=100.0, tolerance=0.0)
    t, poses, _ = loop(c, np.zeros(3), [-0.3, 0.2, 0.4], 10.0, 0.01)
    kr, ka, kb = 1.0, 6.0, -5.0
    slow = (-(ka - kr) + math.sqrt((ka - kr) ** 2 + 4 * kr * kb)) / 2
    late = t >= 4.0
    assert rate(t[late], poses[late, 2]) == pytest.approx(-slow, rel=0.02)
    assert rate(t[late], np.hypot(poses[late, 0], poses[late, 1])) == pytest.approx(kr, rel=0.02)


def test_stops_within_the_tolerance(state):
    """Inside the arrival distance the command is zero, outside it is not."""
    c = GoToPose(tolerance=1e-3)
    assert not c(state(np.array([0.0009, 0.0, 0.3])), np.zeros(3), 0.0).any()
    assert c(state(np.array([0.0011, 0.0, 0.3])), np.zeros(3), 0.0).any()


def test_goal_behind_backs_up(loop):
    """Goal 1 m straight behind, same heading: the robot reverses (v < 0) without turning
    around, and arrives."""
    c = GoToPose(tolerance=0.0)
    _, poses, cmds = loop(c, np.zeros(3), [1.0, 0.0, 0.0], 15.0, 0.01)
    assert (cmds[:, 0] <= 0).all()
    assert np.abs(poses[:, 2]).max() < 1e-9
    assert np.abs(poses[-1]).max() < 1e-3
