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
    caster_collider_names,
    wheel_collider_names,
    wheel_floor_pairs,
)
from wmr_mujoco.models.params import SimParams
from wmr_mujoco.robots.diffdrive.builder import build
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams
from wmr_mujoco.sim.floor_contact import WheelMap


def test_the_drive_wheels_and_the_ball_caster_are_found():
    # Wheels: bodies on hinges only (what WheelMap reads); the ball caster: a body on one
    # ball joint. The chassis (free joint) is neither.
    robot = build(DiffDriveParams())
    assert sorted(wheel_collider_names(robot)) == ["left_wheel_collision",
                                                   "right_wheel_collision"]
    assert caster_collider_names(robot) == ["caster_collision"]


def test_pairs_are_the_wheels_and_the_caster_with_the_remedy():
    model = load("diffdrive")
    p = DiffDriveParams()
    floor = model.geom("floor").id
    wheels = WheelMap.of(model)
    paired = {int(g) for g in model.pair_geom2}
    assert set(model.pair_geom1) == {floor}
    wheel_geoms = {g for g in range(model.ngeom) if wheels.geom_wheel[g] >= 0}
    assert paired == wheel_geoms | {model.geom("caster_collision").id}
    d = p.sim.floor_impedance
    np.testing.assert_array_equal(model.pair_solimp[:, :2], d)
    # Friction damping B_f = 1/Δt in MuJoCo's direct form (0, −B_f d).
    np.testing.assert_allclose(model.pair_solreffriction[:, 1], -d / p.sim.timestep)
    np.testing.assert_allclose(model.pair_solref[:, 0],
                               max(p.sim.contact_timeconst,
                                   WHEEL_PAIR_STEPS * p.sim.timestep))
    assert model.opt.impratio == pytest.approx(common.sliding_impratio(d))


@pytest.mark.parametrize("rolling", [False, True])
def test_the_caster_pair_keeps_the_casters_condim_and_friction(rolling):
    # A pair overrides its geoms' condim and friction; the caster-drag measurement reads
    # the contact's (condim 6 and the collision class's rolling coefficient with rolling
    # friction), so the pair carries the caster geom's own.
    p = DiffDriveParams()
    p = dataclasses.replace(p, caster=dataclasses.replace(p.caster, rolling_friction=rolling))
    model = load("diffdrive", p)
    k = next(i for i in range(model.npair)
             if model.pair_geom2[i] == model.geom("caster_collision").id)
    assert model.pair_dim[k] == (6 if rolling else 3)
    mu = p.sim.friction
    np.testing.assert_allclose(model.pair_friction[k], (mu, mu, common.TORSIONAL_FRICTION,
                                                        common.ROLLING_FRICTION,
                                                        common.ROLLING_FRICTION))


@pytest.mark.parametrize("robot", ["diffdrive", "single_steer", "double_steer", "tricycle"])
def test_every_floor_contact_has_the_impedance_the_impratio_is_set_for(robot):
    # The pairs set the model's impratio to SLIDING_GRIP/d (one value for the whole model):
    # a friction row's regulariser is its normal row's (1 − d)/d over impratio, so every
    # floor contact must carry the pairs' d for impratio · d = SLIDING_GRIP. A contact left
    # at the collision class's d ≈ 0.95 (the ball caster before its pair) got impratio · d
    # ≈ 9500: friction rows ~1e4 times stiffer than grip needs, which made Newton's
    # Hessian too ill-conditioned for MuJoCo Warp's float32 Cholesky (NaN within 0.1 s;
    # docs/batch.md). efc_KBIP[:, 2] is the impedance MuJoCo used in each row.
    from wmr_mujoco.bench.floor_runs import settled

    run = settled(robot)
    m, d = run.model, run.data
    floor = m.geom("floor").id
    contacts = [c for c in d.contact[:d.ncon] if floor in c.geom]
    assert len(contacts) == m.npair  # every collider rests on the floor, each paired
    imp = np.array(d.efc_KBIP).reshape(-1, 4)[:, 2]
    for c in contacts:
        assert m.opt.impratio * imp[c.efc_address] == pytest.approx(common.SLIDING_GRIP)


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
    assert len(bare.contact.get_children("pair")) == 3  # two wheels and the caster


@pytest.mark.parametrize("value", [-0.001, 5e-5, 0.02])
def test_bad_floor_impedance_is_named(value):
    with pytest.raises(ValueError, match="floor_impedance"):
        SimParams(floor_impedance=value)
