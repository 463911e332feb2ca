"""The scripted success benchmark and its confidence bound."""

import math

import pytest

from wmr_mujoco.bench import env_success


def test_wilson_lower_bound_closed_forms():
    # k = n: the bound is n / (n + z²) (Wilson 1927); k = 0: zero.
    assert env_success.wilson_lower(100, 100) == pytest.approx(100 / (100 + 1.96**2))
    assert env_success.wilson_lower(0, 50) == pytest.approx(0.0, abs=1e-15)
    assert env_success.wilson_lower(50, 100) < 0.5


def test_success_rate_counts_seeded_episodes():
    r = env_success.success_rate("wmr/DiffDrive-GoToGoal-v0", episodes=2, seed=0)
    assert r["episodes"] == 2 and r["successes"] + len(r["failed"]) == 2
    assert "| wmr/DiffDrive-GoToGoal-v0 | " in env_success.row("wmr/DiffDrive-GoToGoal-v0", r)
    assert math.isfinite(r["seconds"])


def test_bad_arguments_exit_2(capsys):
    with pytest.raises(SystemExit) as exc:
        env_success.main(["--episodes", "0"])
    assert exc.value.code == 2
    assert "--episodes 0 (valid: 1 to 10000)" in capsys.readouterr().err
