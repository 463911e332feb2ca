"""The environment throughput benchmark runs and reports its figures (no timing asserts)."""

import pytest

from wmr_mujoco.bench import env_throughput


def test_measure_reports_every_loop_and_ratio():
    m = env_throughput.measure("wmr/Disc-GoToGoal-v0", seconds=0.05, repeats=1, vector=2)
    assert set(m) >= {"env", "vector", "sync", "drive", "bare", "env_ratio", "vector_ratio",
                      "sync_ratio", "drive_ratio", "reset_ms", "frame_skip"}
    assert all(m[k] > 0 for k in ("env", "vector", "sync", "drive", "bare", "reset_ms"))
    assert m["env_ratio"] == pytest.approx(m["env"] / m["bare"])
    assert m["frame_skip"] == 10  # 20 ms control period / 2 ms timestep
    assert "| wmr/Disc-GoToGoal-v0 | 10 |" in env_throughput.table({"wmr/Disc-GoToGoal-v0": m})
    line = env_throughput.summary({"wmr/Disc-GoToGoal-v0": m}, 2, 1, 0.05)
    assert "worst vector / bare" in line and "(native, 2 worlds)" in line
    # The exit status judges the env and the native vector ratios, the worse of the two.
    assert env_throughput.worst({"a": m}) == min(m["env_ratio"], m["vector_ratio"])


def test_the_replayed_episode_is_a_solved_one():
    """The loops replay the scripted controller's episode: it ends in success, so the
    figures are those of a policy that drives the robot as the task wants."""
    import gymnasium as gym

    env = gym.make("wmr/Whipple-StayUpright-v0")
    rec = env_throughput.record(env)
    # Not toppled: the whole 10 s episode at 100 Hz.
    assert len(rec.actions) == 1000 and rec.controls.shape == (1000, env.unwrapped.robot.model.nu)


def test_unknown_ids_are_named(capsys):
    with pytest.raises(SystemExit) as exc:
        env_throughput.main(["wmr/Nope-v0"])
    assert exc.value.code == 2
    assert "unknown environment ids ['wmr/Nope-v0']; valid: wmr/" in capsys.readouterr().err
