"""The roller-wheel robots' twist errors: jumps allowed to land a few samples apart."""

import numpy as np
import pytest

from wmr_mujoco.robots.roller_wheels.twist_errors import event_aligned_error, twist_metrics
from wmr_mujoco.validation.metrics import Target


def test_twist_metrics_scale_each_component_by_hand():
    # Reference: u peaks at 0.3 m/s, r at 1 rad/s, L = 0.2 m: the u, v scale is
    # max(0.3, 0.2·1) = 0.3 m/s, the r scale 0.3/0.2 = 1.5 rad/s. Errors 0.003 m/s in u
    # (1 % of 0.3), 0 in v, 0.03 rad/s in r (2 % of 1.5).
    ref = np.array([[0.0, 0.0, 0.0], [0.3, 0.0, 1.0]])
    other = ref + np.array([[0.0, 0.0, 0.0], [0.003, 0.0, 0.03]])
    rows = {m.name: m for m in twist_metrics("M", ref, other, 0.2)}
    assert rows["M: worst u error"].value == pytest.approx(1.0, rel=1e-12)
    assert rows["M: worst v error"].value == 0.0
    assert rows["M: worst r error"].value == pytest.approx(2.0, rel=1e-12)
    assert rows["M: RMS r error"].value == pytest.approx(0.03 / 2 ** 0.5, rel=1e-12)


def test_event_aligned_error_forgives_a_jump_one_sample_late_only():
    # A unit step at sample 5 against the same step at sample 6: pointwise the whole jump
    # (1) at sample 5; within one sample nothing; two samples late: the whole jump again.
    x = (np.arange(12) >= 5).astype(float)
    late1 = (np.arange(12) >= 6).astype(float)
    late2 = (np.arange(12) >= 7).astype(float)
    assert event_aligned_error(x, late1, 0).max() == 1.0
    assert event_aligned_error(x, late1, 1).max() == 0.0
    assert event_aligned_error(x, late2, 1).max() == 1.0
    # Symmetric in its arguments.
    assert np.array_equal(event_aligned_error(late1, x, 1), event_aligned_error(x, late1, 1))


def test_event_aligned_error_keeps_a_wrong_jump_size_and_an_offset():
    # The same instant, a jump of 1 against one of 1.2: the 0.2 mismatch stays (the
    # neighbours offer no better match); a constant offset 0.05 stays everywhere.
    k = np.arange(10)
    x = (k >= 4).astype(float)
    y = 1.2 * (k >= 4)
    assert event_aligned_error(x, y, 1).max() == pytest.approx(0.2, abs=1e-15)
    assert np.allclose(event_aligned_error(x, x + 0.05, 1), 0.05, atol=1e-15)


def test_event_aligned_error_on_a_smooth_ramp_is_bounded_by_one_step_of_change():
    # x = 0.01 k, y = x + 0.03: pointwise 0.03; with one sample either way the closest
    # neighbour is 0.01 nearer (0.02), never below the offset less one step's change.
    x = 0.01 * np.arange(50.0)
    e = event_aligned_error(x, x + 0.03, 1)
    assert e[5:-5] == pytest.approx(np.full(40, 0.02), abs=1e-12)


def test_event_aligned_error_rejects_bad_input():
    with pytest.raises(ValueError, match="shift = -1"):
        event_aligned_error(np.zeros(3), np.zeros(3), -1)
    with pytest.raises(ValueError, match="shift = 1.5"):
        event_aligned_error(np.zeros(3), np.zeros(3), 1.5)
    with pytest.raises(ValueError, match="same"):
        event_aligned_error(np.zeros(3), np.zeros(4), 1)


def test_twist_metrics_with_a_shift_judge_aligned_and_report_pointwise():
    # r jumps by 0.5 rad/s at sample 3 in the reference and at sample 4 in the other;
    # L = 0.2, u = v = 0 so the r scale is peak |r| = 1 rad/s: aligned 0 %, pointwise 50 %.
    ref = np.zeros((8, 3))
    ref[:, 2] = 0.5 + 0.5 * (np.arange(8) >= 3)
    other = ref.copy()
    other[:, 2] = 0.5 + 0.5 * (np.arange(8) >= 4)
    rows = {m.name: m for m in twist_metrics("M", ref, other, 0.2,
                                                {"r": Target.derived(1, "d")}, shift=1)}
    assert rows["M: worst r error"].value == 0.0
    assert rows["M: worst r error"].target.value == 1
    assert rows["M: worst r error, sample by sample"].value == pytest.approx(50.0)
    assert rows["M: worst r error, sample by sample"].target is None


def test_event_aligned_error_retimes_the_trace_as_a_whole():
    # Two components jumping at sample 5 in x; in y the first jumps one sample late and
    # the second one sample early. One match per sample cannot serve both: at sample 5
    # (and 4) one component's whole jump remains, where matching each column apart would
    # forgive both.
    k = np.arange(12)
    x = np.column_stack([k >= 5, k >= 5]).astype(float)
    y = np.column_stack([k >= 6, k >= 4]).astype(float)
    assert event_aligned_error(x, y, 1).max() == 1.0
    assert event_aligned_error(x[:, 0], y[:, 0], 1).max() == 0.0
    assert event_aligned_error(x[:, 1], y[:, 1], 1).max() == 0.0
    with pytest.raises(ValueError, match="scale"):
        event_aligned_error(x, y, 1, scale=(1.0, 0.0))
