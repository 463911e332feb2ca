"""The random-steps family: its registry entries, schedule, sensors and judged metrics."""

from __future__ import annotations

import dataclasses
import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.robots import get_spec
from wmr_mujoco.sim.floor_contact import FloorRecorder, WheelMap
from wmr_mujoco.validation import floor_family as ff
from wmr_mujoco.validation.scenarios import ScenarioKind


def test_the_family_has_the_required_draws_and_varies_a_full_turn():
    s = get_spec("omni3").scenario(ff.NAME)
    assert s.kind is ScenarioKind.MEASUREMENT
    assert s.family is not None and s.family.draws >= 20  # issue 24: >= 20 per family
    phase = next(v for v in s.family.vary if v.name == ff.WHEEL_PHASE)
    assert phase.high - phase.low == pytest.approx(2.0 * math.pi)


def test_schedule_starts_with_a_step_to_the_box_surface_and_stays_inside():
    bounds = np.array([0.3, 0.3, 1.0])
    u = ff.schedule(bounds, 7)
    assert u.shape == (100, 3)  # 10 s at one input per 0.1 s
    # The step from rest is as large as the box allows in its direction.
    assert np.max(np.abs(u[0]) / bounds) == pytest.approx(1.0)
    assert np.all(np.abs(u) <= bounds)
    np.testing.assert_array_equal(u, ff.schedule(bounds, 7))  # seeded


def test_sensors_read_what_the_wheel_map_reads():
    # The contact sensors and WheelMap.read both read MuJoCo's contacts of the wheel
    # geoms with the floor after each step: after the settle they agree exactly, sample
    # by sample, and in depth to rounding. The collision class's contact (floor impedance
    # 0) lets the wheels leave the floor, so both readings see lifts.
    spec = get_spec("omni3")
    model, wheels = ff._sensed(spec, dataclasses.replace(spec.params_type(),
                                                         floor_impedance=0.0))
    data = mujoco.MjData(model)
    for _ in range(200):
        mujoco.mj_step(model, data)
    rng = np.random.default_rng(3)
    rec = FloorRecorder(WheelMap.of(model), 300)
    rows = []
    for k in range(300):
        if k % 50 == 0:
            data.ctrl[:] = rng.uniform(-20.0, 20.0, model.nu)
        mujoco.mj_step(model, data)
        rec.record(data)
        rows.append(data.sensordata.copy())
    from wmr_mujoco.sim.floor_contact import sensor_columns, sensor_reading

    a = rec.reading()
    b = sensor_reading(wheels.wheels, sensor_columns(model, wheels.wheels), np.array(rows))
    assert a.off_floor.any()  # the test drives wheels off the floor
    np.testing.assert_array_equal(a.off_floor, b.off_floor)
    np.testing.assert_allclose(a.depth, b.depth, atol=1e-12)


def test_a_member_reads_the_lifting_of_the_plain_contact():
    # omni3 with the collision class's contact (floor_impedance 0) lifts its wheels after
    # steps (docs/floor-contact.md: the push 2 μ s / t_c exceeds g at a slip of cm/s):
    # the family must see it, far above the 1 % bound, on a 2 s run.
    spec = get_spec("omni3")
    params = dataclasses.replace(spec.params_type(), floor_impedance=0.0)
    member = dataclasses.replace(spec.scenario(ff.NAME), duration=2.0).member(
        {ff.WHEEL_PHASE: 0.3, ff.INPUTS: 0.5})
    result = ff.measure(spec, member, params)
    step, whole = (m.value for m in result.metrics[:2])
    assert step > 5.0 and whole > 1.0
    assert all(m.target is not None and m.target.kind == "requirement"
               for m in result.metrics[:3])
    assert result.metrics[3].target is None  # the tilt is reported, not judged


def test_the_disc_keeps_its_wheel_down():
    # The disc carries the remedy (docs/rolling-disc.md § 8): the push μ d s/Δt stays
    # under g, so not one sample may be off the floor; its weight rests (1 − d) g t_c²
    # deep, under the 0.5 mm bound.
    spec = get_spec("disc")
    member = dataclasses.replace(spec.scenario(ff.NAME), duration=2.0).member(
        {ff.WHEEL_PHASE: 1.0, ff.INPUTS: 0.25})
    step, whole, depth, _ = (m.value for m in ff.measure(spec, member).metrics)
    assert step == 0.0 and whole == 0.0
    assert depth <= 0.5


def test_tilt_is_the_angle_of_the_body_z_axis():
    # A rotation by α about a horizontal axis tilts z by α; about z it tilts nothing.
    a = math.radians(30.0)
    about_x = [math.cos(a / 2), math.sin(a / 2), 0.0, 0.0]
    about_y = [math.cos(a / 2), 0.0, math.sin(a / 2), 0.0]
    about_z = [math.cos(a / 2), 0.0, 0.0, math.sin(a / 2)]
    np.testing.assert_allclose(ff._tilt_deg(np.array([about_x, about_y, about_z])),
                               [30.0, 30.0, 0.0], atol=1e-9)


def test_command_bounds_are_sampled_once_per_spec_and_handed_out_as_copies():
    # The family's members share the sampled bounds: equal on every call, and a caller
    # changing its copy changes no later member's.
    spec = get_spec("bicycle")
    assert spec.command_range is None  # its bounds are sampled from its scenarios
    first = ff.command_bounds(spec)
    first[:] = -1.0
    again = ff.command_bounds(spec)
    assert np.all(again > 0.0)
    assert again.tobytes() == ff.command_bounds(spec).tobytes()
