"""The contact roller and the hand-over instant of the hybrid model's wheels."""

import math

import numpy as np
import pytest

from wmr_mujoco.analytic.planar import wrap_angle
from wmr_mujoco.robots.omni3.runs import hybrid
from wmr_mujoco.robots.roller_wheels.omni_modes import lowest, switch_fraction


def _exact(model, th: np.ndarray) -> np.ndarray:
    """The definition: ``argmin_k |wrap(ζ_k + θ − π)|`` through ``wrap_angle``."""
    return np.argmin(np.abs(wrap_angle(model.rollers.angles + th[..., None] - math.pi)),
                     axis=-1)


@pytest.mark.parametrize("scale", [1.0, 100.0, 9000.0, 1e5])
def test_lowest_is_the_definitions_argmin(scale):
    # Equal indices (integers: no tolerance), from a turn to beyond the fast path's 1e4 rad.
    model = hybrid()
    th = np.random.default_rng(3).uniform(-scale, scale, (20000, 3))
    np.testing.assert_array_equal(lowest(model, th), _exact(model, th))


def test_lowest_at_a_hand_over_tie_is_the_definitions():
    # Wheel angles on the ties between two rollers (half the 30° spacing, so the two
    # lowest are equally low) and a few ulp to either side: the fallback's index.
    model = hybrid()
    gap = 2 * math.pi / model.rollers.angles.size
    ties = math.pi + (np.arange(-60, 60) + 0.5)[:, None] * gap
    th = ties + np.array([0.0, 1e-15, -4e-16])
    np.testing.assert_array_equal(lowest(model, th), _exact(model, th))


def test_lowest_roller_is_the_one_at_the_bottom():
    # θ putting roller k's angle at π (straight down): k, whatever the turns added.
    model = hybrid()
    angles = model.rollers.angles
    for k, zeta in enumerate(angles):
        th = np.full((1, 3), math.pi - zeta + 2 * math.pi * (k - 5))
        assert lowest(model, th).tolist() == [[k, k, k]]


def test_switch_fraction_is_where_both_rollers_are_equally_low():
    # The old roller past the bottom, φ_old from 0.4 s to 0.8 s (s the rollers' spacing),
    # its neighbour coming, φ_new = φ_old − s: the hand-over is where |φ_old| = |φ_new|,
    # φ_old = s/2, a quarter of the step. Neither phase crosses 0 or ±π, so g is linear
    # in θ; the model's roller angles (read from its file) are equally spaced to 1e-12
    # rad, which moves the fraction by ~1e-12 / (0.4 s) ≈ 5e-12: 1e-10 allowed.
    model = hybrid()
    angles = model.rollers.angles
    order = np.argsort(angles)
    gap = 2 * math.pi / angles.size
    old, new = order[4], order[3]  # neighbours: ζ_new = ζ_old − s
    th0 = np.array([[math.pi - angles[old] + 0.4 * gap] * 3])
    frac = switch_fraction(model, th0, th0 + 0.4 * gap, np.full((1, 3), old),
                           np.full((1, 3), new))
    assert frac[0] == pytest.approx(0.25, abs=1e-10)


def test_switch_fraction_of_a_run_without_hand_over_is_the_whole_step():
    model = hybrid()
    th = np.zeros((2, 3))
    modes = lowest(model, th)
    assert switch_fraction(model, th, th + 0.01, modes, modes).tolist() == [1.0, 1.0]


def test_roller_gap_is_omni3s_spacing():
    # omni3's 12 rollers (two rings of 6, offset by half a spacing) are 30° apart; the
    # angles come from the model file, equal to 1e-12 rad.
    assert hybrid().roller_gap == pytest.approx(math.pi / 6, abs=1e-11)
