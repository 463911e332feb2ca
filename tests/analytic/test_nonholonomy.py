import numpy as np
import pytest

from wmr_mujoco.analytic import bicycle, nonholonomy, unicycle


def _unicycle_fields():
    return (lambda q: unicycle.input_fields(q)[:, 0], lambda q: unicycle.input_fields(q)[:, 1])


def test_unicycle_bracket_is_sideways(rng):
    g1, g2 = _unicycle_fields()
    for phi in rng.uniform(-3, 3, 5):
        q = np.array([0.3, -0.1, phi])
        np.testing.assert_allclose(nonholonomy.lie_bracket(g1, g2, q),
                                   [np.sin(phi), -np.cos(phi), 0.0], atol=1e-8)
        assert nonholonomy.accessibility_rank([g1, g2], q, depth=1) == 2
        assert nonholonomy.accessibility_rank([g1, g2], q, depth=2) == 3


def test_bicycle_needs_depth_three():
    ell = 1.0
    g1 = lambda q: bicycle.input_fields(q, ell)[:, 0]  # noqa: E731
    g2 = lambda q: bicycle.input_fields(q, ell)[:, 1]  # noqa: E731
    q = np.array([0.0, 0.0, 0.3, 0.2])
    assert nonholonomy.accessibility_rank([g1, g2], q, depth=2) == 3
    assert nonholonomy.accessibility_rank([g1, g2], q, depth=3) == 4


def test_cycle_moves_sideways_by_the_closed_form():
    """forward d, turn Δ, back d, turn back: exact net (d(1 − cos Δ), −d sin Δ)."""
    g1, g2 = _unicycle_fields()
    for d, turn in [(0.5, 0.3), (1.0, 1.2), (0.2, -0.7)]:
        end = nonholonomy.bracket_cycle_durations(g1, g2, np.zeros(3), d, turn)
        np.testing.assert_allclose(end[:2], nonholonomy.unicycle_cycle_displacement(d, turn),
                                   atol=1e-10)
        assert end[2] == pytest.approx(0.0, abs=1e-12)


def test_small_cycle_follows_the_bracket():
    """Δq = ε² [g1, g2] + O(ε³)."""
    g1, g2 = _unicycle_fields()
    q0 = np.array([0.0, 0.0, 0.4])
    bracket = nonholonomy.lie_bracket(g1, g2, q0)
    for eps in (0.1, 0.05):
        dq = nonholonomy.bracket_cycle(g1, g2, q0, eps) - q0
        assert np.linalg.norm(dq - eps**2 * bracket) < 0.6 * eps**3
