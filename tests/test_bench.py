"""The benchmark code runs and reports sane figures (no timing assertions)."""

from wmr_mujoco.bench import median_time, step_speed


def test_step_speed_reports_every_path():
    res = step_speed("disc", repeats=1, pairs=1, nstep=200, target_s=0.02)
    assert set(res) >= {"loop_steps_per_s", "rollout1_steps_per_s", "rolloutN_steps_per_s",
                        "rollout_speedup", "loop_rtf", "process_ceiling"}
    assert all(v > 0 for v in res.values())


def test_median_time_calls_fn():
    calls = []
    assert median_time(lambda: calls.append(1), repeats=3) >= 0
    assert len(calls) == 4  # one warm-up
