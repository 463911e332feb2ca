"""The floor study's table: one row per robot and setting, quick runs labelled."""

from __future__ import annotations

import dataclasses
import types

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


def test_collision_cost_is_timed_in_cpu_time(monkeypatch):
    """The collision figure reads the table's clock, this process's CPU time: with a
    process clock that advances 1 ms per reading (and a wall clock that refuses to be
    read), each model's figure is 1 ms over its ``calls`` calls, exactly."""
    ticks = iter(range(1000))

    def wall() -> float:
        raise AssertionError("collision_cost read the wall clock")

    clock = types.SimpleNamespace(process_time=lambda: 1e-3 * next(ticks), perf_counter=wall,
                                  time=wall, monotonic=wall)
    monkeypatch.setattr(fs, "time", clock)
    calls = 10
    bits, pairs = fs.collision_cost(rounds=1, calls=calls)
    assert bits == pytest.approx(1e-3 / calls * 1e6, rel=1e-9)  # µs per call
    assert pairs == pytest.approx(1e-3 / calls * 1e6, rel=1e-9)
