"""Explicit wheel-floor pairs: which geoms get them, and what the pairs carry."""

from __future__ import annotations

import dataclasses

import mujoco
import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.lookup import build_scene
from wmr_mujoco.models.builders import common
from wmr_mujoco.models.builders.wheel_pairs import (
    WHEEL_PAIR_STEPS,
    wheel_collider_names,
    wheel_floor_pairs,
)
from wmr_mujoco.models.params import SimParams
from wmr_mujoco.robots.diffdrive.builder import build
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams
from wmr_mujoco.sim.floor_contact import WheelMap


def test_the_drive_wheels_get_pairs_and_the_ball_caster_keeps_its_bits():
    # The ball caster is on a ball joint: not a wheel of WheelMap, and the caster-drag
    # measurement reads its own condim (6 with rolling friction), which a pair would
    # override.
    names = wheel_collider_names(build(DiffDriveParams()))
    assert sorted(names) == ["left_wheel_collision", "right_wheel_collision"]


def test_pairs_are_the_wheels_wheelmap_reads_with_the_remedy():
    model = load("diffdrive")
    p = DiffDriveParams()
    floor = model.geom("floor").id
    wheels = WheelMap.of(model)
    paired = {int(g) for g in model.pair_geom2}
    assert set(model.pair_geom1) == {floor}
    assert paired == {g for g in range(model.ngeom) if wheels.geom_wheel[g] >= 0}
    d = p.sim.floor_impedance
    np.testing.assert_array_equal(model.pair_solimp[:, :2], d)
    # Friction damping B_f = 1/Δt in MuJoCo's direct form (0, −B_f d).
    np.testing.assert_allclose(model.pair_solreffriction[:, 1], -d / p.sim.timestep)
    np.testing.assert_allclose(model.pair_solref[:, 0],
                               max(p.sim.contact_timeconst,
                                   WHEEL_PAIR_STEPS * p.sim.timestep))
    assert model.opt.impratio == pytest.approx(common.sliding_impratio(d))


def test_no_impedance_no_pairs():
    p = DiffDriveParams()
    bits = dataclasses.replace(p, sim=dataclasses.replace(p.sim, floor_impedance=0.0))
    model = mujoco.MjModel.from_xml_string(common.to_xml(build_scene("diffdrive", bits)))
    assert model.npair == 0
    assert model.opt.impratio == bits.sim.impratio


def test_extras_add_pairs_to_a_bare_scene():
    # The checked-in scene.xml is written from a scene without the robot: the pairs are
    # found from the robot the builder makes, not from the scene.
    scene = build_scene("diffdrive", DiffDriveParams())
    bare = type(scene)(model="bare")
    wheel_floor_pairs(build)(bare, DiffDriveParams())
    assert len(bare.contact.get_children("pair")) == 2


@pytest.mark.parametrize("value", [-0.001, 5e-5, 0.02])
def test_bad_floor_impedance_is_named(value):
    with pytest.raises(ValueError, match="floor_impedance"):
        SimParams(floor_impedance=value)
