import mujoco
import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.sim.timing import median_time, paired_ratio, step_loop_time


def test_median_time_calls_fn():
    calls = []
    assert median_time(lambda: calls.append(1), repeats=3) >= 0
    assert len(calls) == 4  # one warm-up


def test_paired_ratio_alternates():
    calls = []
    paired_ratio(lambda: calls.append("slow"), lambda: calls.append("fast"), 2, warmup=False)
    assert calls == ["slow", "fast", "slow", "fast"]


@pytest.mark.parametrize("call", [lambda: paired_ratio(print, print, 0),
                                  lambda: median_time(print, 0)])
def test_bad_repeats_are_refused(call):
    with pytest.raises(ValueError, match="= 0; must be >= 1"):
        call()


def test_step_loop_time_steps_the_model(monkeypatch):
    model = load("disc")
    steps = []
    real_step = mujoco.mj_step
    monkeypatch.setattr(mujoco, "mj_step", lambda m, d: (steps.append(1), real_step(m, d)))
    assert step_loop_time(model, np.zeros(model.nu), 10, repeats=2) > 0
    assert len(steps) == 30  # warm-up and two timed runs of 10 steps
