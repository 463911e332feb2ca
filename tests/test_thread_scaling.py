"""Thread-scaling measurement: what it runs is the physics, and bad sizes are refused."""

import numpy as np
import pytest

from wmr_mujoco.thread_scaling import (
    make_batch,
    paired_rounds,
    process_ceilings,
    sized_batch,
)


@pytest.mark.parametrize("robot", ["bicycle", "omni3"])
def test_threaded_batch_matches_one_thread(robot):
    """Each rollout has its own MjData, so two threads give the one-thread states bit for
    bit; and the identical members of the batch agree with each other."""
    batch = make_batch(robot, 4, nstep=100)
    batch.runner(1)()
    one = batch.state.copy()
    batch.runner(2)()
    assert np.array_equal(one, batch.state)
    assert np.array_equal(one[0], one[3])
    assert np.all(np.isfinite(one))


def test_batch_moves_the_robot():
    """The batch cruises on driving controls: the base travels (not a resting model)."""
    batch = make_batch("disc", 1, nstep=250)
    batch.runner(1)()
    qpos0 = 1  # mjSTATE_FULLPHYSICS starts with time, then qpos
    start, end = batch.initial[0, qpos0:qpos0 + 2], batch.state[0, -1, qpos0:qpos0 + 2]
    # 250 steps of 2 ms at the 1 m/s cruise: about 0.5 m; 0.1 m rules out a standstill.
    assert np.linalg.norm(end - start) > 0.1


def test_sized_batch_is_a_multiple_of_threads():
    batch = sized_batch("disc", threads=3, target_s=0.01)
    assert batch.controls.shape[0] % 3 == 0 and batch.controls.shape[0] >= 6


def test_paired_rounds_interleave_the_keys():
    calls = []
    pairs = {k: (lambda k=k: calls.append(f"{k}1"), lambda k=k: calls.append(f"{k}2"))
             for k in "ab"}
    out = paired_rounds(pairs, 2, warmup=False)
    assert calls == ["a1", "a2", "b1", "b2"] * 2
    assert set(out) == {"a", "b"}


@pytest.mark.parametrize(("call", "match"), [
    (lambda: make_batch("disc", 0), "nbatch = 0"),
    (lambda: make_batch("disc", 1).runner(0), "nthread = 0"),
    (lambda: paired_rounds({}, 0), "rounds = 0"),
    (lambda: process_ceilings({"tank": 2}, 1), "tank"),
    (lambda: process_ceilings({"disc": 0}, 1), r"nbatch\['disc'\] = 0"),
    (lambda: process_ceilings({"disc": 2}, 0), "rounds = 0"),
])
def test_bad_sizes_are_refused(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_process_ceilings_run():
    ceilings = process_ceilings({"disc": 2, "bicycle": 2}, 1, processes=2)
    assert set(ceilings) == {"disc", "bicycle"}
    # N t_alone / max(t_together) is at most N = 2 for work that cannot share anything;
    # a single round can overshoot by the machine's noise (tens of %), not by 50 %.
    assert all(0 < c < 2 * 1.5 for c in ceilings.values())
