"""MuJoCo against the kinematic model under the stepping API, per family of runs."""

from __future__ import annotations

import pytest

from wmr_mujoco.bench import drive_accuracy
from wmr_mujoco.robots import get_spec
from wmr_mujoco.validation import metrics as mt


@pytest.mark.parametrize("name", sorted(drive_accuracy.FAMILIES))
def test_mujoco_runs_stay_within_the_robots_requirement(name: str) -> None:
    """Tolerance: the robot's own validation requirement, the worst position error over
    the run within ``POSITION_PCT`` % of the analytic path, over five seeded draws (speeds,
    turn, start pose, wheel phase) inside its validated envelope."""
    family = drive_accuracy.FAMILIES[name]
    pct = get_spec(family.robot).targets[mt.POSITION_PCT].value
    worst = drive_accuracy.worst_position_pct(family, draws=5, seed=0)
    assert 0.0 < worst <= pct, f"{name}: worst {worst:.3f} % of path > {pct} %"


def test_prints_the_table(capsys: pytest.CaptureFixture[str]) -> None:
    assert drive_accuracy.main(["--draws", "1"]) == 0
    rows = [r for r in capsys.readouterr().out.splitlines() if r.startswith("| ")][1:]
    assert [r.split("|")[1].strip() for r in rows] == list(drive_accuracy.FAMILIES)


def test_bad_draws_are_refused() -> None:
    with pytest.raises(SystemExit):
        drive_accuracy.main(["--draws", "0"])
    with pytest.raises(ValueError, match="draws = 0"):
        drive_accuracy.worst_position_pct(drive_accuracy.FAMILIES["bicycle turns"], 0)
