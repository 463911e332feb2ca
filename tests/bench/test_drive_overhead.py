"""The stepping-overhead benchmark runs and prints its table (no timing asserted)."""

from __future__ import annotations

import pytest

from wmr_mujoco.bench import drive_overhead


def test_prints_one_row_per_robot(capsys: pytest.CaptureFixture[str]) -> None:
    assert drive_overhead.main(["--robot", "diffdrive", "--robot", "whipple", "--steps",
                                "2", "--rounds", "1"]) == 0
    out = capsys.readouterr().out
    rows = [line for line in out.splitlines() if line.startswith("| ")][1:]
    assert [r.split("|")[1].strip() for r in rows] == ["diffdrive", "whipple"]
    assert rows[1].split("|")[6].strip() == "-"  # whipple: no kinematic backend


def test_bad_counts_are_refused() -> None:
    with pytest.raises(SystemExit) as exc:
        drive_overhead.main(["--steps", "0"])
    assert exc.value.code == 2
