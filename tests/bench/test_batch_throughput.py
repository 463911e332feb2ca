"""The batch throughput bench: what it times, and its table."""

import pytest

from wmr_mujoco.bench import batch_throughput as bt


def test_measure_times_the_requested_batch():
    p = bt.measure("diffdrive", "rollout", 3, repeats=1)
    # Steps follow the budget, clipped: 40 000 / 3 robot-steps is above MAX_STEPS.
    assert (p.robot, p.backend, p.worlds, p.steps) == ("diffdrive", "rollout", 3, bt.MAX_STEPS)
    assert p.seconds > 0 and p.throughput == pytest.approx(3 * p.steps / p.seconds)
    with pytest.raises(ValueError, match="worlds = 0"):
        bt.measure("diffdrive", "rollout", 0)


def test_a_budget_sets_the_steps_within_the_clip():
    # 60 robot-steps over 3 worlds: 20 steps each, inside [MIN_STEPS, MAX_STEPS].
    assert bt.measure("diffdrive", "rollout", 3, repeats=1, budget=60).steps == 20


def test_table_has_a_row_per_robot_and_backend():
    points = [bt.Point("diffdrive", "rollout", 1, 100, 0.01),
              bt.Point("diffdrive", "rollout", 8, 100, 0.02),
              bt.Point("diffdrive", "warp", 1, 10, 1.0)]
    text = bt.table(points)
    assert "| robot | backend | N = 1 | N = 8 |" in text
    assert "| diffdrive | rollout | 10 | 40 |" in text  # thousands of robot-steps/s
    assert "| diffdrive | warp | 0.01 | - |" in text


def test_docs_hold_the_markers():
    from wmr_mujoco.bench import batch_parity
    from wmr_mujoco.docs_sync.markers import has_markers

    for marker in (bt.MARKER, bt.GPU_MARKER, batch_parity.MARKER, batch_parity.GPU_MARKER):
        assert has_markers(bt.DOC, marker)
