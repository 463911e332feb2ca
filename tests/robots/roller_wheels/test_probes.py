"""The roller-rate probe's geometry index: each roller geom to its wheel and hinge."""

import mujoco
import numpy as np

from wmr_mujoco import load
from wmr_mujoco.robots.omni3.runs import WHEELS
from wmr_mujoco.robots.roller_wheels.model_info import layout_from_model
from wmr_mujoco.robots.roller_wheels.probes import (
    rate_errors,
    roller_contacts,
    roller_geoms,
    roller_rate_errors,
)


def test_roller_geoms_name_each_rollers_wheel_and_hinge():
    model = load("omni3")
    info = layout_from_model(model, WHEELS)
    wheel, joint = roller_geoms(model, info)
    wheel_bodies = [model.jnt_bodyid[j] for j in info.wheel_joints]
    for g in range(model.ngeom):
        body = model.geom_bodyid[g]
        if wheel[g] >= 0:  # a roller: one hinge, on a wheel's body
            assert model.body_parentid[body] == wheel_bodies[wheel[g]]
            assert model.jnt_bodyid[joint[g]] == body
            assert model.body_jntnum[body] == 1
        else:
            assert model.body_parentid[body] not in wheel_bodies or \
                model.body_jntnum[body] != 1
    counts = np.bincount(wheel[wheel >= 0], minlength=3)
    assert counts.min() == counts.max() > 0  # the three wheels alike


def test_roller_rate_errors_read_the_index_or_build_it():
    model = load("omni3")
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data, 300)  # settled on the floor: rollers in contact
    data.qvel[model.jnt_dofadr[model.joint(WHEELS[0]).id]] = 3.0
    mujoco.mj_forward(model, data)
    info = layout_from_model(model, WHEELS)
    slide = np.array([0.1, 0.2, 0.3])
    got = roller_rate_errors(model, data, info, slide, roller_geoms(model, info))
    assert got == roller_rate_errors(model, data, info, slide)
    assert len(got) >= 3  # a roller of each wheel touches


def test_layout_is_read_once_per_equal_model_and_anew_for_a_changed_one():
    # A family's members share one model: the second read is the first one's result
    # (the same floats, in read-only arrays: no caller changes another's); a model
    # changed in place (its timestep) settles anew and reads a different rolling radius
    # (the settled penetration depends on the step).
    model = load("omni3")
    first = layout_from_model(model, WHEELS)
    again = layout_from_model(model, WHEELS)
    assert again.layout.radii.tobytes() == first.layout.radii.tobytes()
    assert again.layout.positions.tobytes() == first.layout.positions.tobytes()
    assert not again.layout.radii.flags.writeable
    model.opt.timestep *= 2.0
    changed = layout_from_model(model, WHEELS)
    assert changed.layout.radii.tobytes() != first.layout.radii.tobytes()


def test_rate_errors_of_stacked_steps_are_each_steps_own():
    # The probe keeps each step's contact rows and computes the errors of all steps at
    # once: the same floats, in the same order, as step by step (each row's own sums).
    model = load("omni3")
    data = mujoco.MjData(model)
    info = layout_from_model(model, WHEELS)
    rollers = roller_geoms(model, info)
    data.ctrl[:] = [4.0, -2.0, 1.0]
    slide = np.array([0.11, -0.23, 0.05])
    one_by_one, rows = [], []
    for _ in range(60):
        mujoco.mj_step(model, data, 5)
        one_by_one += roller_rate_errors(model, data, info, slide, rollers)
        got = roller_contacts(model, data, info, slide, rollers)
        if got is not None:
            rows.append(got)
    stacked = rate_errors(*(np.concatenate(r) for r in zip(*rows, strict=True)))
    assert len(one_by_one) > 60
    assert np.array(stacked).tobytes() == np.array(one_by_one).tobytes()
