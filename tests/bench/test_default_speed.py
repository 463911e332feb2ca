"""The default-speed table: previous defaults as recorded, a timed row, the table."""

from __future__ import annotations

import math

import pytest

from wmr_mujoco.bench import default_speed as ds
from wmr_mujoco.robots import get_spec

TINY = ds.Rounds(seconds=0.2, rounds=1)


def test_previous_defaults_are_the_recorded_overrides():
    before = ds.previous(get_spec("omni3"))
    assert before is not None
    assert before.floor_impedance == 0.0
    assert before.sim.timestep == ds.PREVIOUS_DEFAULTS["omni3"]["sim.timestep"]
    # Every drivable robot has a record to compare with.
    assert set(ds.drivable()) <= set(ds.PREVIOUS_DEFAULTS)


def test_rows_and_table():
    rows = ds.rows(["bicycle"], TINY)
    assert rows[0]["rtf"] > 0 and rows[0]["rtf_previous"] > 0
    assert "floor pairs" in rows[0]["default"]
    assert "collision class" in rows[0]["previous"]
    text = ds.table(rows, [], TINY, quick=True)
    assert text.startswith("QUICK run")
    assert "| bicycle |" in text and "Peer left out" in text


def test_an_unchanged_robot_has_no_previous_row(monkeypatch):
    """A record equal to today's defaults (no override) gives no previous row."""
    monkeypatch.setattr(ds, "PREVIOUS_DEFAULTS", {**ds.PREVIOUS_DEFAULTS, "disc": {}})
    rows = ds.rows(["disc"], TINY)
    assert rows[0]["previous"] is None and rows[0]["rtf_previous"] is None


def test_unknown_robot_fails_before_any_run():
    with pytest.raises(ValueError, match="nosuch"):
        ds.main(["--quick", "nosuch"])


def test_a_diverging_setting_raises_or_is_nan_when_asked(monkeypatch):
    """The defaults' timing raises on a divergence; a candidate study asks for NaN, and the
    other settings are still timed."""
    from wmr_mujoco.sim.stepping import SimulationDivergedError

    real = ds.prepare_timed

    def prepare(spec, params, seconds):
        if params is not None:
            raise SimulationDivergedError("diverged at t=0.1 s")
        return real(spec, params, seconds)

    monkeypatch.setattr(ds, "prepare_timed", prepare)
    spec = ds.get_spec("disc")
    with pytest.raises(SimulationDivergedError):
        ds.real_time_factors(spec, [None, spec.params_type()], TINY)
    rtf = ds.real_time_factors(spec, [None, spec.params_type()], TINY, diverged_nan=True)
    assert rtf[0] > 0 and math.isnan(rtf[1])


def test_chosen_refuses_a_robot_the_family_does_not_drive(capsys):
    import argparse

    parser = argparse.ArgumentParser(prog="x")
    assert ds.chosen(parser, []) == ds.drivable()
    assert ds.chosen(parser, ["omni3"]) == ["omni3"]
    with pytest.raises(SystemExit):
        ds.chosen(parser, ["whipple"])
    assert "'whipple' is not driven by the random-steps family" in capsys.readouterr().err
