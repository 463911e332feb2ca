"""The column-wise nearest foot gives the floats of the row-wise einsum projection."""

import numpy as np

from wmr_mujoco.loop.control import polyline


def rowwise(xy, window, p):
    """The projection as written on (N, 2) rows with einsum (its reference)."""
    idx = np.arange(len(xy) - 1)[window]
    a, b = xy[idx], xy[idx + 1]
    d = b - a
    t = np.clip(np.einsum("ij,ij->i", p - a, d) / np.einsum("ij,ij->i", d, d), 0.0, 1.0)
    foot = a + t[:, None] * d
    return int(np.argmin(np.einsum("ij,ij->i", foot - p, foot - p))), t


def test_nearest_is_the_rowwise_projection_bit_for_bit():
    # A random walk of 3000 points at several scales, windows as slices (a range of
    # segments) and as index arrays (one that wraps): the same foot index and the same
    # t of every segment, to the bit.
    rng = np.random.default_rng(0)
    for scale in (1e-3, 1.0, 1e3):
        xy = np.cumsum(rng.normal(0.0, scale, (3000, 2)), axis=0)
        seg = polyline.segments(xy)
        for _ in range(200):
            lo = int(rng.integers(0, 2900))
            window = (slice(lo, lo + int(rng.integers(1, 99))) if rng.random() < 0.5
                      else np.mod(np.arange(lo - 50, lo + 50), len(xy) - 1))
            p = xy[lo] + rng.normal(0.0, 3.0 * scale, 2)
            k, t = polyline.nearest(seg, window, float(p[0]), float(p[1]))
            want_k, want_t = rowwise(xy, window, p)
            assert k == want_k
            assert t.tobytes() == want_t.tobytes()


def test_nearest_foot_of_a_point_beside_a_straight_polyline():
    # Points along x every 1 m; (2.25, 1) is nearest segment 2 (from x = 2), a quarter
    # of the way along it: t = 0.25 exactly; beyond the end the foot is the end (t = 1).
    xy = np.stack([np.arange(5.0), np.zeros(5)], axis=1)
    seg = polyline.segments(xy)
    k, t = polyline.nearest(seg, slice(0, 4), 2.25, 1.0)
    assert k == 2 and t[k] == 0.25
    k, t = polyline.nearest(seg, slice(0, 4), 7.0, -1.0)
    assert k == 3 and t[k] == 1.0
    assert seg.dd.tolist() == [1.0] * 4


def test_interp_is_np_interp_bit_for_bit():
    # Random points inside, at, before and after the samples, and inf/NaN: every column's
    # float equals np.interp's (the same formula in the same order).
    rng = np.random.default_rng(1)
    xp = np.cumsum(rng.uniform(1e-3, 0.1, 500))
    cols = [rng.normal(0.0, 3.0, 500) for _ in range(3)]
    xs = np.concatenate([rng.uniform(xp[0] - 1, xp[-1] + 1, 3000), xp[::5],
                         [xp[0], xp[-1], np.inf, -np.inf, np.nan]])
    lists = tuple(c.tolist() for c in cols)
    for x in xs.tolist():
        got = polyline.interp(xp.tolist(), lists, x)
        want = [np.interp(x, xp, c) for c in cols]
        assert np.array(got).tobytes() == np.array(want).tobytes()


def test_search_is_searchsorted():
    xp = np.array([0.0, 0.5, 0.5, 1.0, 2.0])
    for x in (-1.0, 0.0, 0.25, 0.5, 0.75, 2.0, 3.0, np.inf, -np.inf, np.nan):
        assert polyline.search(xp.tolist(), x) == int(np.searchsorted(xp, x))


def test_reach_bounds_the_motion_along_the_polyline():
    # |q(s1) − q(s0)| ≤ ρ |s1 − s0| for points interpolated at random arc lengths, with s a
    # distorted arc length (ρ above 1); the bound is what lets first_beyond skip points.
    rng = np.random.default_rng(2)
    xy = np.cumsum(rng.normal(0.0, 0.1, (400, 2)), axis=0)
    s = np.concatenate([[0.0], np.cumsum(rng.uniform(0.02, 0.2, 399))])
    seg = polyline.segments(xy)
    rho, slack = polyline.reach(seg, s, closed=False)
    a, b = rng.uniform(0, s[-1], (2, 5000))
    qa = np.stack([np.interp(a, s, xy[:, 0]), np.interp(a, s, xy[:, 1])], 1)
    qb = np.stack([np.interp(b, s, xy[:, 0]), np.interp(b, s, xy[:, 1])], 1)
    assert np.all(np.linalg.norm(qa - qb, axis=1) <= rho * np.abs(a - b) + slack)
    assert polyline.reach(seg, np.zeros(400), closed=False)[0] == np.inf  # s stalls


def test_first_beyond_is_the_first_of_the_whole_scan():
    # Chunked from any start at or before the answer: the index of a full scan's first far
    # point; -1 where none is far.
    rng = np.random.default_rng(3)
    xy = np.cumsum(rng.normal(0.0, 0.05, (1000, 2)), axis=0)
    s = np.arange(1000.0)
    def points(a):
        return np.stack([np.interp(a, s, xy[:, 0]), np.interp(a, s, xy[:, 1])], 1)
    ahead = np.linspace(0.0, 999.0, 3000)
    for _ in range(50):
        p, dist = xy[rng.integers(0, 1000)], float(rng.uniform(0.1, 2.0))
        far = np.flatnonzero(np.linalg.norm(points(ahead) - p, axis=1) >= dist)
        want = int(far[0]) if len(far) else -1
        start = int(rng.integers(0, want + 1)) if want >= 0 else 0
        def distances(a, p=p):
            return np.linalg.norm(points(a) - p, axis=1)
        assert polyline.first_beyond(distances, ahead, start, dist) == want
    assert polyline.first_beyond(distances, ahead, 0, 1e9) == -1


def test_finder_answers_later_windows_of_a_point_as_nearest_does():
    # One point, windows shifted around (inside the kept margin, beyond it, round the end
    # of the polyline): every answer is nearest's on that window, to the bit.
    rng = np.random.default_rng(5)
    xy = np.cumsum(rng.normal(0.0, 0.1, (2000, 2)), axis=0)
    seg = polyline.segments(xy)
    finder, n = polyline.Finder(seg), len(xy) - 1
    for _ in range(300):
        p = xy[rng.integers(0, 2000)] + rng.normal(0.0, 0.3, 2)
        first = int(rng.integers(-50, n - 100))
        for shift in (0, 3, -7, 40, 200):
            lo, hi = first + shift, first + shift + int(rng.integers(1, 300))
            window = (slice(lo, hi) if lo >= 0 and hi <= n else np.mod(np.arange(lo, hi), n))
            k, t = finder.nearest(lo, hi, float(p[0]), float(p[1]))
            want_k, want_t = polyline.nearest(seg, window, float(p[0]), float(p[1]))
            assert k == want_k and t.tobytes() == want_t.tobytes()
