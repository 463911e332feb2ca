"""Warp buffers sized from a C MuJoCo probe; an overflow is raised, never silent."""

import copy
import math

import mujoco
import pytest

import wmr_mujoco as wmr
from wmr_mujoco.api import _prepare
from wmr_mujoco.batch import buffers

pytestmark = pytest.mark.extra  # MuJoCo Warp (the gpu extra)


def test_buffers_cover_the_counts_of_an_independent_c_run():
    prep = _prepare("omni3", [0.3, 0.1, 0.5], 0.3, None, "kinematic", 0.5, False)
    got = buffers.measure([prep], steps=150)
    data, ncon, nefc = copy.copy(prep.data), prep.data.ncon, prep.data.nefc
    for ctrl in prep.controls[:150]:
        data.ctrl[:] = ctrl
        mujoco.mj_step(prep.model, data)
        ncon, nefc = max(ncon, data.ncon), max(nefc, data.nefc)
    assert (got.seen_ncon, got.seen_nefc) == (ncon, nefc) and ncon > 0
    assert got.nconmax == max(math.ceil(buffers.MARGIN * ncon) + buffers.SLACK,
                              buffers.collision_pairs(prep.model))
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


PAIRS_XML = """
<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <geom name="wall" type="box" size="0.1 0.1 0.1" pos="2 0 0"/>
    <body name="a" pos="0 0 1">
      <freejoint/>
      <geom name="a" type="sphere" size="0.1"/>
      <body name="b" pos="0 0 0.3">
        <joint type="hinge"/>
        <geom name="b" type="sphere" size="0.1"/>
      </body>
    </body>
    <body name="c" pos="1 0 1">
      <freejoint/>
      <geom name="c" type="sphere" size="0.1"/>
      <geom name="ghost" type="sphere" size="0.1" contype="2" conaffinity="2"/>
    </body>
  </worldbody>
  <contact>
    <exclude body1="a" body2="c"/>
    <pair geom1="floor" geom2="ghost"/>
  </contact>
</mujoco>
"""


def test_collision_pairs_follow_mujocos_filter():
    """By hand: floor and wall are both world (one weld group: no pair); a, b, c each
    meet floor and wall (6); a-b is parent-child (filtered); a-c excluded; b-c one pair;
    ghost (contype 2) meets nothing by filter; plus the explicit floor-ghost pair: 8."""
    model = mujoco.MjModel.from_xml_string(PAIRS_XML)
    assert buffers.collision_pairs(model) == 8


def test_buffers_hold_every_broadphase_candidate():
    prep = _prepare("omni3", [0.3, 0.1, 0.5], 0.05, None, "kinematic", 0.5, False)
    got = buffers.measure([prep], steps=10)
    assert got.pairs == buffers.collision_pairs(prep.model) and got.nconmax >= got.pairs
