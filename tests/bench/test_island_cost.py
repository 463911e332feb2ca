"""The island-cost bench: islands on and off time the same run to the same bytes."""

from __future__ import annotations

import math

import mujoco
import pytest

from wmr_mujoco.bench import island_cost as ic
from wmr_mujoco.bench.default_speed import Rounds, prepare_timed
from wmr_mujoco.robots import get_spec

TINY = Rounds(seconds=0.2, rounds=2)


def test_the_twin_has_islands_on_and_shares_the_run():
    off = prepare_timed(get_spec("diffdrive"), None, 0.2)
    on = ic.with_islands(off)
    assert off.model.opt.disableflags & ic._ISLAND
    assert not on.model.opt.disableflags & ic._ISLAND
    assert on.model is not off.model and on.data is not off.data
    assert (on.state == off.state).all() and on.controls is off.controls


def test_measure_and_table():
    r = ic.measure("diffdrive", TINY)
    assert r.identical
    assert r.rtf_off > 0 and r.rtf_on > 0 and math.isfinite(r.ratio) and r.ratio > 0
    text = ic.table([r], TINY)
    assert "| diffdrive |" in text and "identical to the bit" in text


def test_a_model_with_islands_on_is_refused(monkeypatch):
    real = ic.prepare_timed

    def prepare(spec, params, seconds):
        t = real(spec, params, seconds)
        t.model.opt.disableflags &= ~int(mujoco.mjtDisableBit.mjDSBL_ISLAND)
        return t

    monkeypatch.setattr(ic, "prepare_timed", prepare)
    with pytest.raises(ValueError, match="island discovery on"):
        ic.measure("disc", TINY)


def test_writing_part_of_the_table_is_refused(capsys):
    with pytest.raises(SystemExit):
        ic.main(["--quick", "--write", "disc"])
    assert "leave the robots out" in capsys.readouterr().err


def test_unknown_robot_fails_before_any_run():
    with pytest.raises(ValueError, match="nosuch"):
        ic.main(["--quick", "nosuch"])
