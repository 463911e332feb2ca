"""Stanley (Thrun et al. 2006) closing the loop on the car and unicycle models."""

from __future__ import annotations

import numpy as np
import pytest

from wmr_mujoco.loop.control import paths
from wmr_mujoco.loop.control.stanley import Stanley


@pytest.mark.parametrize("kind", ["car", "unicycle"])
def test_front_axle_error_decays_at_the_gain(loop, rate, kind):
    """Start 5 cm off a line: the front axle's error obeys ė = −v_f sin(atan(k e/v)), so
    once small it decays as e^{−k t} (k = 1.5 1/s). Rate fitted over 1-4 s within 3 %
    (10 ms hold: O(k Δt) ≈ 1.5 %; v_f/v = 1/cos δ − 1 < 1e-3 once δ is small)."""
    ell, k = 0.4, 1.5
    c = Stanley(speed=0.5, gain=k, wheelbase=ell, kind=kind)
    t, poses, _ = loop(c, paths.line(20.0), [0.0, 0.05, 0.0], 4.0, 0.01, ell)
    front_y = poses[:, 1] + ell * np.sin(poses[:, 2])
    late = t >= 1.0
    assert rate(t[late], front_y[late]) == pytest.approx(k, rel=0.03)


def test_follows_the_lane_change(loop):
    """The error law ė = −v_f sin(atan(k e/v)) holds on a curved path too (ė is the normal
    component of the front axle's velocity, and δ cancels the path's heading): only the
    10 ms hold disturbs it, by a heading drift of at most v κ Δt per step, i.e. a rate
    v² κ Δt in ė, which the loop at rate k holds to v² κ_max Δt / k = 2.8e-4 m
    (κ_max = 0.2225 1/m). The front axle stays within that bound all along."""
    ell = 0.4
    path = paths.lane_change()
    c = Stanley(speed=0.5, gain=2.0, wheelbase=ell)
    _, poses, _ = loop(c, path, [0.0, 0.0, 0.0], path.length / 0.5 - 2.0, 0.01, ell)
    front = poses[:, :2] + ell * np.stack([np.cos(poses[:, 2]), np.sin(poses[:, 2])], 1)
    errors = np.array([path.cross_track(p)[0] for p in front])
    bound = 0.5**2 * np.abs(path.curvature).max() * 0.01 / 2.0
    assert np.abs(errors).max() < bound
