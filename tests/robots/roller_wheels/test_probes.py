"""The roller-rate probe's geometry index: each roller geom to its wheel and hinge."""

import mujoco
import numpy as np

from wmr_mujoco import load
from wmr_mujoco.robots.omni3.runs import WHEELS
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.model_info import layout_from_model
from wmr_mujoco.robots.roller_wheels.probes import (
    PENDING_STEPS,
    RollerRateProbe,
    SampleTwist,
    WheelRateProbe,
    YawRippleProbe,
    rate_errors,
    roller_contacts,
    roller_geoms,
    roller_rate_errors,
)
from wmr_mujoco.validation.traces import Sample


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


def _contact_rows(model, data, info, slide):
    """Each floor contact of a roller, one by one: (rel, axis, |s|, |ω|) as arrays."""
    wheel_bodies = [model.jnt_bodyid[j] for j in info.wheel_joints]
    rows = []
    for i in range(data.ncon):
        c = data.contact[i]
        geom = c.geom2 if model.geom_bodyid[c.geom1] == 0 else c.geom1
        body = model.geom_bodyid[geom]
        parent = model.body_parentid[body]
        if model.body_jntnum[body] != 1 or parent not in wheel_bodies:
            continue
        j = model.body_jntadr[body]
        rows.append((c.pos - data.xanchor[j], data.xaxis[j].copy(),
                     abs(slide[wheel_bodies.index(parent)]),
                     abs(data.qvel[model.jnt_dofadr[j]])))
    return [np.array(col) for col in zip(*rows, strict=True)]


class _CountingAdapter:
    """A body-twist adapter (input = twist) that counts its ``twist`` calls."""

    def __init__(self, layout):
        self.layout, self.calls = layout, 0

    def twist(self, u, analytic_state):
        self.calls += 1
        return np.asarray(u, float)


def test_roller_probe_over_many_steps_is_the_step_by_step_errors():
    # The probe copies each step's contacts and frames and reads PENDING_STEPS steps at
    # once: over more steps than that, with the twist changing, its errors are those of
    # each step's contacts read one by one here, float for float. The yaw-ripple probe,
    # sharing the twists, asks the adapter once per sample.
    model = load("omni3")
    data = mujoco.MjData(model)
    info = layout_from_model(model, WHEELS)
    adapter = _CountingAdapter(info.layout)
    twists = SampleTwist(adapter)
    roller = RollerRateProbe(info, adapter, None, after=-1.0, twists=twists)
    yaw = YawRippleProbe(info.base_body, adapter, after=-1.0, twists=twists)
    data.ctrl[:] = [4.0, -2.0, 1.0]
    want, steps = [], PENDING_STEPS + 40
    for k in range(steps):
        mujoco.mj_step(model, data, 2)
        u = np.array([0.1 + 1e-3 * (k % 7), -0.05, 0.3])
        sample = Sample(k, 0.0, model, data, u, data.ctrl.copy(), np.zeros(3))
        roller.observe(sample)
        yaw.observe(sample)
        rows = _contact_rows(model, data, info, ok.roller_slide_speeds(info.layout, u))
        want += rate_errors(*rows) if rows else []
    roller.metrics()
    assert adapter.calls == steps
    assert len(want) > steps  # rollers of every wheel touch
    assert np.array(roller.errors).tobytes() == np.array(want).tobytes()
    assert yaw.commanded == [0.3] * steps


def test_wheel_rate_probe_is_the_relative_norm_of_the_rate_error():
    # |θ̇ − θ̇_cmd| / |θ̇_cmd| with np.linalg.norm, the same float; below a commanded norm
    # of 0.5 (and up to ``after``) nothing is recorded.
    model = load("omni3")
    data = mujoco.MjData(model)
    dofs = tuple(int(model.jnt_dofadr[model.joint(w).id]) for w in WHEELS)
    probe = WheelRateProbe(dofs)
    data.qvel[list(dofs)] = [1.0, -2.0, 0.5]
    for t, ctrl in ((2.0, [1.5, -1.0, 0.25]), (2.0, [0.3, 0.0, 0.1]), (0.5, [3.0, 0, 0])):
        probe.observe(Sample(0, t, model, data, np.zeros(3), np.array(ctrl), np.zeros(3)))
    want = np.linalg.norm(np.array([1.0, -2.0, 0.5]) - [1.5, -1.0, 0.25]) \
        / np.linalg.norm([1.5, -1.0, 0.25])
    assert probe.errors == [float(want)]
