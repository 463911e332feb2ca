"""The floor study's table: one row per robot and setting, quick runs labelled."""

from __future__ import annotations

import dataclasses

import pytest

from wmr_mujoco.bench import floor_study as fs

TINY = dataclasses.replace(fs.QUICK, draws=2, duration=0.5, timed=0.2)


def test_rows_and_table_for_the_disc():
    rows = fs.rows(TINY, ["disc"])
    assert [r["robot"] for r in rows] == ["disc"]
    r = rows[0]
    assert r["members"] == 2
    assert r["worst"][0] == 0.0 and r["worst"][1] == 0.0  # the disc's remedy
    assert all(x > 0 for x in r["rtf"])
    text = fs.table(rows, TINY, quick=True)
    assert text.startswith("QUICK run")
    assert "| disc | default: " in text


def test_robots_whose_defaults_changed_get_a_previous_row():
    labels = [label for label, _ in fs._settings("omni3")]
    assert labels == ["default", "previous default"]
    assert [label for label, _ in fs._settings("disc")] == ["default"]


def test_unknown_robot_fails_before_any_run():
    with pytest.raises(ValueError, match="nosuch"):
        fs.main(["--no-write", "--quick", "nosuch"])
