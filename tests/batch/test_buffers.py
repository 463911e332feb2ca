"""Warp buffers sized from a C MuJoCo probe; an overflow is raised, never silent."""

import copy
import math

import mujoco
import pytest

import wmr_mujoco as wmr
from wmr_mujoco.api import _prepare
from wmr_mujoco.batch import buffers


def test_buffers_cover_the_counts_of_an_independent_c_run():
    prep = _prepare("omni3", [0.3, 0.1, 0.5], 0.3, None, "kinematic", 0.5, False)
    got = buffers.measure([prep], steps=150)
    data, ncon, nefc = copy.copy(prep.data), prep.data.ncon, prep.data.nefc
    for ctrl in prep.controls[:150]:
        data.ctrl[:] = ctrl
        mujoco.mj_step(prep.model, data)
        ncon, nefc = max(ncon, data.ncon), max(nefc, data.nefc)
    assert (got.seen_ncon, got.seen_nefc) == (ncon, nefc) and ncon > 0
    assert got.nconmax == math.ceil(buffers.MARGIN * ncon) + buffers.SLACK
    assert got.njmax == math.ceil(buffers.MARGIN * nefc) + buffers.SLACK
    with pytest.raises(ValueError, match="steps = -1"):
        buffers.measure([prep], steps=-1)


def test_overflow_is_an_error_naming_the_buffer(monkeypatch):
    """From the unsettled start (settle 0) diffdrive has contacts but no constraint row yet;
    buffers sized from that start alone (no probe steps, no margin, one spare row) run out
    as the wheels press in: the nefc overflow must be raised, with the member."""
    monkeypatch.setattr(buffers, "MARGIN", 1.0)
    monkeypatch.setattr(buffers, "SLACK", 1)
    with pytest.raises(RuntimeError, match=r"overflow \(NEFC.*member 0"):
        wmr.simulate_batch("diffdrive", [[0.5, 0.0]], 0.1, settle=0.0, backend="warp",
                           probe_steps=0)
