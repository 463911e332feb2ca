"""Pure pursuit (Coulter 1992) closing the loop on the unicycle and car models."""

from __future__ import annotations

import numpy as np
import pytest

from wmr_mujoco.loop.control import paths
from wmr_mujoco.loop.control.pure_pursuit import PurePursuit


def test_curvature_of_the_arc_to_the_goal_point(state):
    """From the origin heading +x, a goal point on the line y = 0.3 at distance L = 0.6 lies
    at bearing α = asin(0.5); the arc through both, tangent to +x, has radius L²/(2·0.3)."""
    c = PurePursuit(lookahead=0.6)
    kappa = c.curvature(state(np.zeros(3)), paths.from_curve(
        "y=0.3", lambda t: (np.stack([t, 0 * t + 0.3], 1), np.stack([1 + 0 * t, 0 * t], 1),
                            np.zeros((len(t), 2))), 5.0))
    assert kappa == pytest.approx(2 * 0.3 / 0.36, rel=1e-3)  # goal found on a 1/4 sample grid


def test_line_response_is_the_linear_second_order_system(loop):
    """Start 2 cm off a line, aligned: e(t) = e₀ e^{−σt}(cos σt + sin σt), σ = v/L (the
    double root pair (v/L)(−1 ± i); ė(0) = 0). Nonlinear terms are O((e₀/L)²) = 0.1 % of e₀
    and the 5 ms hold O(σ Δt) = 0.4 %: within 2 % of e₀ throughout."""
    v, ell, e0 = 0.5, 0.6, 0.02
    c = PurePursuit(speed=v, lookahead=ell)
    t, poses, _ = loop(c, paths.line(20.0), [0.0, e0, 0.0], 6.0, 0.005)
    s = v / ell
    expected = e0 * np.exp(-s * t) * (np.cos(s * t) + np.sin(s * t))
    np.testing.assert_allclose(poses[:, 1], expected, atol=0.02 * e0)


@pytest.mark.parametrize("wheelbase", [None, 0.5])
def test_no_steady_state_error_on_a_circle(loop, wheelbase):
    """On a circle r² = R² is the only steady state (module docstring): starting 0.2 m
    outside, after three laps the cross-track error is below 1 mm (the 5 ms hold of a
    curvature command adds O(v Δt κ L) ≈ 1e-4 m)."""
    path = paths.circle(2.0)
    c = PurePursuit(speed=0.5, lookahead=0.6, wheelbase=wheelbase)
    _, poses, _ = loop(c, path, [0.0, -0.2, 0.0], 3 * path.length / 0.5, 0.005, wheelbase)
    errors = [path.cross_track(p)[0] for p in poses[-400:]]
    assert np.abs(errors).max() < 1e-3
