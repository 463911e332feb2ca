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


# -- the learning tasks' paths: random bounded curvature, Hermite, run-out, tracking ------

@pytest.mark.parametrize("seed", range(5))
def test_random_path_respects_its_curvature_bound(seed):
    """|κ| ≤ κ_max by construction (Σ|a_k| ≤ κ_max); the polyline's own turning between
    chords DS apart follows it to O(κ' DS), well inside 1e-3 of the bound here."""
    start = np.array([0.3, -0.2, 0.7])
    path = paths.random_path(np.random.default_rng(seed), start, length=4.0, max_curvature=1.5)
    np.testing.assert_allclose(path.xy[0], start[:2])
    assert path.heading[0] == pytest.approx(start[2])
    assert np.abs(path.curvature).max() <= 1.5
    chord = np.diff(path.xy, axis=0)
    turn = np.diff(np.unwrap(np.arctan2(chord[:, 1], chord[:, 0])))
    assert np.abs(turn / paths.DS).max() <= 1.5 * (1 + 1e-3)
    # s is arc length; each chord is the mean of two unit vectors Δψ = κ DS apart, times
    # DS: shorter by a factor cos(Δψ/2) ≈ 1 − (κ DS)²/8, at most 2.3e-6 m here.
    assert path.length == 4.0
    np.testing.assert_allclose(np.hypot(*chord.T), paths.DS,
                               atol=paths.DS * (1.5 * paths.DS) ** 2 / 8 * (1 + 1e-6))


def test_random_path_is_seeded_and_checked():
    a = paths.random_path(np.random.default_rng(3), np.zeros(3), 2.0, 1.0)
    b = paths.random_path(np.random.default_rng(3), np.zeros(3), 2.0, 1.0)
    np.testing.assert_array_equal(a.xy, b.xy)
    with pytest.raises(ValueError, match="length"):
        paths.random_path(np.random.default_rng(0), np.zeros(3), -1.0, 1.0)


def test_hermite_path_joins_the_two_poses_and_extend_runs_on_straight():
    """The basis gives p(1) = p₁ and p'(1) ∥ m₁ exactly (to rounding)."""
    start, goal = np.array([0.0, 0.0, 0.0]), np.array([2.0, 1.0, np.pi / 2])
    path = paths.hermite_path(start, goal)
    np.testing.assert_allclose(path.xy[-1], goal[:2], atol=1e-12)
    assert path.heading[-1] == pytest.approx(goal[2], abs=1e-9)
    assert path.heading[0] == pytest.approx(start[2], abs=1e-12)
    longer = paths.extend(path, 0.5)
    assert longer.length == pytest.approx(path.length + 0.5, abs=1e-12)
    np.testing.assert_allclose(longer.xy[-1], goal[:2] + np.array([0.0, 0.5]), atol=1e-12)
    assert longer.at(path.length + 0.25).curvature == 0.0


@pytest.mark.parametrize("seed", range(3))
def test_track_finds_what_closest_finds(seed):
    """A point driving along a random path with a lateral offset (under the 1/κ_max =
    0.67 m radius: the nearest point is unique within reach): track from the last answer
    lands on the same foot as the exhaustive closest() (to rounding)."""
    rng = np.random.default_rng(seed)
    path = paths.extend(paths.random_path(rng, np.zeros(3), 4.0, 1.5), 1.0)
    s = 0.0
    for along in np.arange(0.0, 4.5, 0.03):
        q = path.at(along)
        off = 0.4 * np.sin(along)
        p = q.position + off * np.array([-np.sin(q.heading), np.cos(q.heading)])
        near, tracked = path.closest(p), path.track(p, s)
        assert tracked.s == pytest.approx(near.s, abs=1e-9)
        np.testing.assert_allclose(tracked.position, near.position, atol=1e-9)
        s = tracked.s


def test_positions_are_at_vectorised():
    path = paths.figure_eight()
    s = np.array([0.5, 3.0, 20.0])
    np.testing.assert_allclose(path.positions(s), [path.at(x).position for x in s],
                               atol=1e-12)


def _closest_by_index(path, point, hint, window=paths.HINT_WINDOW):
    """closest() as it was written with index arrays (the reference of the slices)."""
    p = np.asarray(point, float)[:2]
    n = len(path.s)
    if hint is None:
        idx = np.arange(n - 1)
    else:
        h = float(np.mod(hint, path.length) if path.closed else np.clip(hint, 0.0, path.length))
        lo, hi = np.searchsorted(path.s, [h - window, h + window])
        idx = np.arange(lo - 1, hi + 1)
        idx = np.mod(idx, n - 1) if path.closed else idx[(idx >= 0) & (idx < n - 1)]
    a, b = path.xy[idx], path.xy[idx + 1]
    d = b - a
    t = np.clip(np.einsum("ij,ij->i", p - a, d) / np.einsum("ij,ij->i", d, d), 0.0, 1.0)
    foot = a + t[:, None] * d
    k = int(np.argmin(np.einsum("ij,ij->i", foot - p, foot - p)))
    return path.at(path.s[idx[k]] + t[k] * (path.s[idx[k] + 1] - path.s[idx[k]]))


@pytest.mark.parametrize("name", ["lane_change", "figure_eight", "circle", "random_spline"])
def test_closest_searches_its_window_by_slices_with_the_same_floats(name):
    # The window as array views (no fancy-index copies) must find the very same point,
    # bit for bit: hints near both ends (a closed path's window wraps there), hints off
    # an open path's ends, no hint; the wrapped and clipped arc lengths as numpy's.
    path = paths.make_path(name, 1)
    rng = np.random.default_rng(5)
    for _ in range(400):
        s0 = rng.uniform(-1.5, path.length + 1.5)
        q = path.positions(np.array([s0]))[0] + rng.normal(scale=0.3, size=2)
        hint = None if rng.random() < 0.1 else s0 + rng.normal(scale=0.4)
        got, want = path.closest(q, hint), _closest_by_index(path, q, hint)
        assert (got.s, got.heading, got.curvature) == (want.s, want.heading, want.curvature)
        assert got.position.tobytes() == want.position.tobytes()


def test_lookahead_is_the_full_scan_and_closest_answers_are_fresh():
    # The lookahead skips samples surely inside its circle: the point is that of the scan of
    # every sample ahead (as written before the skip). A kept closest-point answer comes
    # back as a new PathPoint: changing one does not change the next.
    rng = np.random.default_rng(4)
    for path in (paths.random_spline(5), paths.figure_eight(), paths.lane_change()):
        for _ in range(300):
            s = float(rng.uniform(0.0, path.length))
            p = path.at(s).position + rng.normal(0.0, 0.2, 2)
            dist, hint = float(rng.choice([0.1, 0.6, 3.0])), s + float(rng.normal(0.0, 0.2))
            s0 = path.closest(p, hint).s
            step = path.s[1]
            ahead = s0 + np.arange(0.0, (2.0 * dist + 4.0 * step), step / 4.0)
            if not path.closed:
                ahead = ahead[ahead <= path.length]
            far = np.flatnonzero(np.linalg.norm(path.positions(ahead) - p, axis=1) >= dist)
            want = path.at(ahead[far[0]] if len(far) else ahead[-1]) if len(ahead) else \
                path.at(path.length)
            got = path.lookahead(p, dist, hint)
            assert (got.s, got.heading) == (want.s, want.heading)
            assert got.position.tobytes() == want.position.tobytes()
    q = path.closest((1.0, 0.5), 1.0)
    q.position[:] = 99.0
    assert path.closest((1.0, 0.5), 1.0).position.tolist() != [99.0, 99.0]
