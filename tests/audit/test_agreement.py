"""The agreement table's generator, on one robot."""

from __future__ import annotations

from wmr_mujoco.audit.agreement import row


def test_diffdrive_row_agrees_with_validate():
    # One validation scenario (its arc) keeps the test short; the full table runs all.
    line = row("diffdrive", duration=1.0, draws=1, only=("arc",))
    cells = [c.strip() for c in line.strip("|").split("|")]
    assert cells[0] == "diffdrive" and cells[1] == "(2,0)"
    assert cells[-1] == "yes", cells


def test_a_robot_outside_the_theory_is_listed_with_its_reason():
    assert "not audited" in row("whipple")
