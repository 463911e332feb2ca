"""Splitting members over devices and joining them back; a real two-shard Warp run."""

import numpy as np
import pytest

import wmr_mujoco as wmr
from wmr_mujoco.batch.shard import join, split


@pytest.mark.parametrize("members", [1, 2, 7, 8, 9, 100])
@pytest.mark.parametrize("shards", [1, 2, 3, 8])
def test_split_tiles_members_evenly(members, shards):
    ranges = split(members, shards)
    assert len(ranges) == min(members, shards)
    flat = [i for r in ranges for i in r]
    assert flat == list(range(members))  # contiguous, in order, each member once
    sizes = [len(r) for r in ranges]
    assert min(sizes) >= 1 and max(sizes) - min(sizes) <= 1


def test_join_restores_member_order():
    ranges = split(5, 2)  # [0, 1, 2], [3, 4]
    parts = [[f"m{i}" for i in r] for r in ranges]
    assert join(parts, ranges) == ["m0", "m1", "m2", "m3", "m4"]
    with pytest.raises(ValueError, match="returned 1 results for 2 members"):
        join([parts[0], parts[1][:1]], ranges)
    with pytest.raises(ValueError, match="member 0 is in two shards"):
        join([["a"], ["b"]], [range(0, 1), range(0, 1)])
    with pytest.raises(ValueError, match="both must be >= 1"):
        split(0, 2)


@pytest.mark.extra  # MuJoCo Warp (the gpu extra)
def test_two_shards_on_one_cpu_equal_one_shard():
    """Worlds are independent in MuJoCo Warp, so splitting 3 members into shards of 2 and
    1 (both on the CPU) and joining them gives the one-shard result bit for bit, in order;
    members with different inputs and frictions make a mix-up visible."""
    from dataclasses import replace

    from wmr_mujoco.robots.diffdrive.params import DiffDriveParams

    base = DiffDriveParams()
    params = [replace(base, sim=replace(base.sim, friction=mu)) for mu in (0.3, 1.0, 0.6)]
    inputs = [[0.5, 0.3], [0.2, -0.4], [0.4, 1.0]]
    one = wmr.simulate_batch("diffdrive", inputs, 0.2, params, backend="warp", devices=["cpu"])
    two = wmr.simulate_batch("diffdrive", inputs, 0.2, params, backend="warp",
                             devices=["cpu", "cpu"])
    np.testing.assert_array_equal(one.states, two.states)
    end = one.pose[:, -1]  # members' final poses differ pairwise (> 1 mm or 1 mrad)
    assert min(np.abs(end[i] - end[j]).max() for i in range(3) for j in range(i)) > 1e-3
