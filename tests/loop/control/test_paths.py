"""Paths: geometry checked against closed forms and against each other's definitions."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad

from wmr_mujoco.loop.control import paths


@pytest.mark.parametrize("name", list(paths.PATHS))
def test_curvature_is_the_heading_rate(name):
    """κ = dψ/ds: the stored curvature (from p', p'') against the stored heading
    differentiated along the stored arc length. Central differences on the fine grid
    err by O(h² κ''): 1e-3 1/m covers the sharpest path here (κ up to 1.2 1/m, h < 5 mm)."""
    p = paths.make_path(name, seed=5)
    dpsi = np.gradient(p.heading, p.s)
    np.testing.assert_allclose(dpsi[2:-2], p.curvature[2:-2], atol=1e-3)


def test_circle_closed_forms():
    """R = 2: κ = 1/R, length 2πR, centre (0, R). Trapezoid of a constant speed is exact
    (1e-9); interpolated positions sit on chords, at most R (1 − cos(h/2R)) ≈ 1e-6 m in."""
    c = paths.circle(2.0)
    np.testing.assert_allclose(c.curvature, 0.5, atol=1e-9)
    assert c.length == pytest.approx(4 * np.pi, abs=1e-9)
    s = np.linspace(0, 20, 37)
    r = [np.hypot(*(c.at(x).position - [0, 2])) for x in s]
    np.testing.assert_allclose(r, 2.0, atol=2e-6)
    # A point inside a counter-clockwise circle is on its left: positive cross-track.
    # The foot on the polyline may lie anywhere on the nearest chord: s within one sample
    # spacing h = 4π/4000.
    h = c.s[1]
    e, s0 = c.cross_track([0.0, 0.5])
    assert e == pytest.approx(0.5, abs=1e-6) and s0 == pytest.approx(0.0, abs=h)
    e, s1 = c.cross_track([3.0, 2.0])
    assert e == pytest.approx(-1.0, abs=1e-6) and s1 == pytest.approx(np.pi, abs=h)


def test_figure_eight_length_and_crossing():
    """Length against adaptive quadrature of |p'(τ)| (trapezoid error ~1e-6 m here). At the
    self-crossing the hint keeps the branch being followed."""
    a = 4.0
    f = paths.figure_eight(a)
    exact, _ = quad(lambda t: np.hypot(a * np.cos(t), a * np.cos(2 * t)), 0, 2 * np.pi,
                    limit=200)
    assert f.length == pytest.approx(exact, abs=1e-4)
    half = f.length / 2
    assert f.closest([0.0, 0.0], hint=0.1).s == pytest.approx(0.0, abs=1e-3)
    assert f.closest([0.0, 0.0], hint=half - 0.1).s == pytest.approx(half, abs=1e-3)
    # The branches cross at right angles to each other: headings ±45° (tan = a cos 2τ / a cos τ).
    assert f.at(0.0).heading == pytest.approx(np.pi / 4, abs=1e-6)


def test_lane_change_shift():
    """Ends straight, shifted by the offset; curvature zero at both ends (C² smoothstep)."""
    p = paths.lane_change(offset=1.2, transition=5.0, straight=3.0)
    assert p.start_pose == pytest.approx([0, 0, 0], abs=1e-12)
    end = p.at(p.length)
    assert end.position[1] == pytest.approx(1.2, abs=1e-12)
    assert end.heading == pytest.approx(0.0, abs=1e-9)
    # κ ≈ y'' = 60 offset u / tr² rises linearly from the joint: within one sample
    # spacing h of it, at most 60 · 1.2 · (h / 5) / 25.
    h = p.s[1]
    assert abs(p.at(3.0).curvature) <= 60 * 1.2 * (h / 5) / 25 and abs(end.curvature) < 1e-9


def test_lookahead_is_coulters_goal_point():
    """On the x axis from (1, 0.5) the goal point at L = 1 is (1 + √(1 − 0.25), 0)."""
    p = paths.line(10.0)
    g = p.lookahead([1.0, 0.5], 1.0)
    assert g.position[0] == pytest.approx(1 + np.sqrt(0.75), abs=2e-3)  # sample step /4
    assert np.hypot(*(g.position - [1.0, 0.5])) >= 1.0
    assert p.lookahead([9.9, 0.0], 1.0).s == pytest.approx(10.0)  # past the end: the end


def test_random_spline_seeded():
    """The same seed gives the same path, another seed another; it starts at the origin
    heading along +x (the clamped first derivative)."""
    a, b, c = paths.random_spline(3), paths.random_spline(3), paths.random_spline(4)
    np.testing.assert_array_equal(a.xy, b.xy)
    assert np.abs(a.xy[-1] - c.xy[-1]).max() > 0.1
    assert a.start_pose == pytest.approx([0, 0, 0], abs=1e-9)


@pytest.mark.parametrize("bad", [{"name": "spiral"}, {"name": "line", "seed": -1},
                                 {"name": "line", "seed": 1.5}])
def test_bad_input(bad):
    with pytest.raises(ValueError, match="spiral|seed"):
        paths.make_path(**bad)
    with pytest.raises(ValueError, match="radius"):
        paths.circle(0.0)
