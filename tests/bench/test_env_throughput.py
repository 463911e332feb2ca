"""The environment throughput benchmark runs and reports its figures (no timing asserts)."""

import pytest

from wmr_mujoco.bench import env_throughput


def test_measure_reports_every_loop_and_ratio():
    m = env_throughput.measure("wmr/Disc-GoToGoal-v0", seconds=0.05, repeats=1, vector=2)
    loops = ("env", "vector", "vector16", "vector64", "sync", "drive")
    assert set(m) >= {*loops, "bare", *(f"{k}_ratio" for k in loops), "reset_ms", "frame_skip"}
    assert all(m[k] > 0 for k in (*loops, "bare", "reset_ms"))
    assert m["vector64_ratio"] == pytest.approx(m["vector64"] / m["bare"])
    assert m["env_ratio"] == pytest.approx(m["env"] / m["bare"])
    assert m["frame_skip"] == 10  # 20 ms control period / 2 ms timestep
    assert "| wmr/Disc-GoToGoal-v0 | 10 |" in env_throughput.table({"wmr/Disc-GoToGoal-v0": m})
    line = env_throughput.summary({"wmr/Disc-GoToGoal-v0": m}, 2, 1, 0.05)
    assert "worst native vector / bare at 16 worlds" in line and "at 2 worlds" in line
    # The exit status judges the native vector ratio at 16 worlds.
    assert env_throughput.worst({"a": m}) == m["vector16_ratio"]


def test_unknown_ids_are_named(capsys):
    with pytest.raises(SystemExit) as exc:
        env_throughput.main(["wmr/Nope-v0"])
    assert exc.value.code == 2
    assert "unknown environment ids ['wmr/Nope-v0']; valid: wmr/" in capsys.readouterr().err


def test_every_bad_option_is_named_with_its_range(capsys):
    # All bad options in one message, each with its valid range, before any environment
    # is made (exit 2, as argparse's own errors).
    with pytest.raises(SystemExit) as exc:
        env_throughput.main(["--seconds", "0", "--repeats", "3", "--vector", "65"])
    err = capsys.readouterr().err
    assert exc.value.code == 2
    assert "--seconds 0.0 (valid: 0.05 to 30)" in err and "--vector 65 (valid: 1 to 64)" in err
    assert "--repeats" not in err.split("error:")[-1]  # 3 is valid: not named
