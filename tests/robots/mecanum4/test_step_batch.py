"""The grouped step translations' responses, prepared together, are each run's own."""

import dataclasses

import pytest

from wmr_mujoco.models.loading import load
from wmr_mujoco.robots.mecanum4 import SPEC, step_batch, traction
from wmr_mujoco.robots.mecanum4.kinematics import kinematic_adapter
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels.roller_stick_slip import step_response


def _members(draws=2):
    return SPEC.scenario("8 translations (step)").members(0, draws)


def test_the_registry_prepares_with_step_batch():
    assert SPEC.prepare is step_batch.prepare


def test_step_runs_are_the_drawn_steps_of_each_group_member():
    # Two draws of the eight stepped translations: sixteen runs, each with its draw's
    # speed; the ramped group has no step run (its command starts at 0).
    runs = step_batch.step_runs(_members())
    assert len(runs) == 16
    assert all(r.draw for r in runs)
    assert step_batch.step_runs(SPEC.scenario("8 translations (ramp)").members(0, 2)) == []


def test_prepared_responses_are_the_runs_own_bit_for_bit():
    members = _members()
    step_batch.prepare(members, None)
    model = load(SPEC)
    p = MecanumParams()
    for run in step_batch.step_runs(members):
        twist = run.input_at(0.0)
        got = step_batch.take(twist, run.duration, None)
        assert got is not None
        want = step_response(*traction.step_platform(model, p, twist), run.duration)
        for field in dataclasses.fields(want):
            a, b = getattr(got, field.name), getattr(want, field.name)
            assert a.shape == b.shape and a.tobytes() == b.tobytes(), field.name
        assert step_batch.take(twist, run.duration, None) is None  # taken once


def test_the_adapter_takes_a_prepared_response_and_computes_one_otherwise(monkeypatch):
    run = dataclasses.replace(step_batch.step_runs(_members(1))[0], duration=0.3)
    model = load(SPEC)
    alone = kinematic_adapter(run, model, None).step  # nothing prepared: its own
    step_batch.prepare([], None)
    marker = dataclasses.replace(alone, time=alone.time + 0.0)
    monkeypatch.setitem(step_batch._READY,
                        step_batch._key(run.input_at(0.0), run.duration, None), marker)
    assert kinematic_adapter(run, model, None).step is marker
    assert kinematic_adapter(run, model, None).step is not marker  # taken: computed again


def test_a_new_prepare_drops_what_was_left_and_too_many_runs_are_refused(monkeypatch):
    step_batch.prepare(_members(1), None)
    assert len(step_batch._READY) == 8
    step_batch.prepare([], None)
    assert not step_batch._READY
    monkeypatch.setattr(step_batch, "MAX_READY", 10)
    with pytest.raises(ValueError, match="16 step runs to prepare; at most 10"):
        step_batch.prepare(_members(), None)
