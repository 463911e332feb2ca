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
