"""Thread-scaling measurement: what it runs is the physics, and bad sizes are refused."""

import numpy as np
import pytest

from wmr_mujoco.bench.thread_scaling import batch_size, make_batch, scaling


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


def test_batch_size_is_a_multiple_of_threads():
    n = batch_size("disc", threads=3, target_s=0.01)
    assert n % 3 == 0 and n >= 6


@pytest.mark.parametrize(("call", "match"), [
    (lambda: make_batch("disc", 0), "nbatch = 0"),
    (lambda: make_batch("disc", 1).runner(0), "nthread = 0"),
    (lambda: scaling(["tank"], 1), "tank"),
    (lambda: scaling(["disc"], 0), "rounds = 0"),
])
def test_bad_sizes_are_refused(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_scaling_reports_threads_beside_processes():
    res = scaling(["disc", "bicycle"], 1, workers=2, target_s=0.02)
    assert set(res) == {"disc", "bicycle"}
    for figures in res.values():
        assert figures["threads"] == 2 and figures["nbatch"] % 2 == 0
        # Ratios of two timings: positive and finite. Their size is the machine's (and its
        # load's), so it is reported by the bench, never asserted in a test.
        for key in ("rollout_speedup", "process_ceiling"):
            assert np.isfinite(figures[key]) and figures[key] > 0


@pytest.mark.parametrize("robot", ["whipple", "disc_free"])
def test_a_robot_without_a_kinematic_scenario_is_a_value_error(robot):
    from wmr_mujoco.bench.thread_scaling import driving_controls

    with pytest.raises(ValueError, match=f"robot '{robot}' has no kinematic scenario to "
                       "drive; valid robots: disc, bicycle"):
        driving_controls(None, robot)
