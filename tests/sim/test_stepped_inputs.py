"""Seeded random stepped inputs: reproducible, inside the box, a step every period."""

from __future__ import annotations

import numpy as np
import pytest

from wmr_mujoco.sim.stepped_inputs import random_steps, step_draws

BOUNDS = (0.3, 0.3, 1.0)


def test_random_steps_are_seeded_bounded_and_one_per_period():
    u = random_steps(BOUNDS, 10.0, seed=4, period=0.1)
    assert u.shape == (100, 3)
    np.testing.assert_array_equal(u, random_steps(BOUNDS, 10.0, seed=4, period=0.1))
    assert not np.array_equal(u, random_steps(BOUNDS, 10.0, seed=5, period=0.1))
    assert (np.abs(u) <= np.asarray(BOUNDS)).all()
    # Independent uniform draws: consecutive periods never repeat, and over 100 draws
    # each component spans most of its range (the chance that 100 uniform draws all miss
    # the outer 20 % on one side is 0.9^100 ≈ 3e-5).
    assert (np.diff(u, axis=0) != 0).all()
    assert (u.max(axis=0) > 0.8 * np.asarray(BOUNDS)).all()
    assert (u.min(axis=0) < -0.8 * np.asarray(BOUNDS)).all()


def test_a_partial_last_period_counts():
    assert random_steps(BOUNDS, 0.25, seed=0, period=0.1).shape == (3, 3)


def test_step_draws_lie_on_the_box_surface():
    u = step_draws(BOUNDS, 50, seed=1)
    assert u.shape == (50, 3)
    np.testing.assert_allclose(np.max(np.abs(u) / np.asarray(BOUNDS), axis=1), 1.0)
    np.testing.assert_array_equal(u, step_draws(BOUNDS, 50, seed=1))


@pytest.mark.parametrize(("call", "match"), [
    (lambda: random_steps((0.3, -1.0), 1.0, 0), "bounds"),
    (lambda: random_steps((0.3, float("nan")), 1.0, 0), "bounds"),
    (lambda: random_steps(BOUNDS, 0.0, 0), "duration"),
    (lambda: random_steps(BOUNDS, 1e9, 0), "duration"),
    (lambda: random_steps(BOUNDS, 1.0, 0, period=2.0), "period"),
    (lambda: step_draws(BOUNDS, 0, 0), "count"),
    (lambda: step_draws(BOUNDS, 10**9, 0), "count"),
])
def test_bad_input_is_named(call, match):
    with pytest.raises(ValueError, match=match):
        call()
