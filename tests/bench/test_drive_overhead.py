"""The stepping-overhead benchmark runs and prints its table (no timing asserted)."""

from __future__ import annotations

import pytest

from wmr_mujoco.bench import drive_overhead


def _rows(out: str) -> list[list[str]]:
    """The table's body rows, split into cells."""
    rows = [line for line in out.splitlines() if line.startswith("| ")][1:]
    return [[cell.strip() for cell in row.split("|")[1:-1]] for row in rows]


def test_prints_one_row_per_robot(capsys: pytest.CaptureFixture[str]) -> None:
    assert drive_overhead.main(["--robot", "diffdrive", "--robot", "whipple", "--steps",
                                "2", "--rounds", "1"]) == 0
    rows = _rows(capsys.readouterr().out)
    assert [r[0] for r in rows] == ["diffdrive", "whipple"]
    assert rows[1][5] == "-"  # whipple: no kinematic backend
    assert all(len(r) == 10 for r in rows)
    # Rates and ratios are positive numbers.
    assert all(float(cell) > 0 for r in rows for cell in r[2:5] + r[6:])


def test_wheels_mode_has_no_kinematic_column(capsys: pytest.CaptureFixture[str]) -> None:
    assert drive_overhead.main(["--robot", "diffdrive", "--mode", "wheels", "--steps", "2",
                                "--rounds", "1"]) == 0
    out = capsys.readouterr().out
    assert "mode 'wheels'" in out
    assert _rows(out)[0][5] == "-"


def test_bad_counts_are_refused() -> None:
    with pytest.raises(SystemExit) as exc:
        drive_overhead.main(["--steps", "0"])
    assert exc.value.code == 2
