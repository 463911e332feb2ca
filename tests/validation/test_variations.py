"""The generic variations the runner applies to a member: input scale, lead-in, duration,
wheel phase (each checked on what it changes, in a cheap robot's run)."""

import dataclasses
import math

import mujoco
import numpy as np
import pytest

import wmr_mujoco
from wmr_mujoco.robots import get_spec
from wmr_mujoco.validation import variations as var
from wmr_mujoco.validation.family import Family, Vary
from wmr_mujoco.validation.runner import prepare, run_scenario
from wmr_mujoco.validation.scenarios import Scenario
from wmr_mujoco.validation.signals import const


def _with(s: Scenario, *vary: Vary) -> Scenario:
    return dataclasses.replace(s, family=Family(tuple(vary), 1))


def test_input_scale_and_lead_in_shape_the_inputs():
    s = _with(Scenario("disc", "x", (const(1.0), const(0.5))), var.speeds(), var.channel(1),
              var.lead_in(0.0, 1.0))
    m = s.member({var.INPUT_SCALE: 0.8, var.input_scale(1): 1.1, var.LEAD_IN: 0.5})
    # u(t) = min(1, t / T) · s ⊙ u_nominal(t): exact arithmetic, compared to 1e-15.
    np.testing.assert_allclose(m.input_at(2.0), [0.8, 0.8 * 1.1 * 0.5], rtol=1e-15)
    np.testing.assert_allclose(m.input_at(0.25), 0.5 * np.array([0.8, 0.44]), rtol=1e-15)
    np.testing.assert_array_equal(s.input_at(0.25), [1.0, 0.5])  # nominal untouched


def test_a_drawn_duration_is_the_members_duration():
    s = _with(Scenario("disc", "x", (const(1.0),), duration=10.0), var.duration(2.0, 3.0))
    assert s.member({var.DURATION: 2.5}).duration == 2.5
    assert s.member({}).duration == 10.0


def test_a_channel_the_scenario_lacks_or_a_kinematic_family_of_unknown_names_fails():
    s = _with(Scenario("disc", "x", (const(1.0),)), var.channel(3))
    with pytest.raises(ValueError, match="channel 3"):
        s.member({var.input_scale(3): 1.1})
    with pytest.raises(ValueError, match="varies only what the runner applies"):
        Scenario("disc", "x", (const(1.0),), family=Family((Vary("mass", 1, 2),), 2))


def test_input_scale_changes_the_simulated_speed_by_the_factor():
    spec = get_spec("diffdrive")
    nominal = spec.scenario("straight")
    s = _with(nominal, var.channel(0))
    runs = {f: run_scenario(spec, s.member({var.input_scale(0): f})) for f in (0.8, 1.2)}
    base = run_scenario(spec, dataclasses.replace(nominal, family=None))
    dist = {f: np.linalg.norm(np.diff(r.trace.arrays()["sim"][[0, -1], :2], axis=0))
            for f, r in [*runs.items(), (1.0, base)]}
    # Each run tracks its own commanded path within the 0.5 % of path its scenario
    # passes, so the distance ratio is the factor within 2 × 0.5 % = 1 %.
    for f in (0.8, 1.2):
        assert dist[f] / dist[1.0] == pytest.approx(f, rel=1e-2)


def test_wheel_phase_turns_every_wheel_joint_and_nothing_else():
    spec = get_spec("diffdrive")
    s = _with(spec.scenario("straight"), Vary(var.WHEEL_PHASE, 0.0, 1.0, "rad"))
    model = wmr_mujoco.load("diffdrive")
    data = mujoco.MjData(model)
    before = data.qpos.copy()
    joints = ("left_wheel", "right_wheel")
    var.add_wheel_phase(model, data, joints, 0.3)
    adr = [model.jnt_qposadr[model.joint(j).id] for j in joints]
    np.testing.assert_array_equal(data.qpos[adr] - before[adr], 0.3)
    rest = np.setdiff1d(np.arange(model.nq), adr)
    np.testing.assert_array_equal(data.qpos[rest], before[rest])
    # Through the runner: after the 0.5 s settle at rest (wheel servos at zero rate)
    # the wheels still differ by the phase, within 1e-3 rad of settling creep.
    a = prepare(spec, s.member({}))
    b = prepare(spec, s.member({var.WHEEL_PHASE: 0.3}))
    diff = b.data.qpos[adr] - a.data.qpos[adr]
    np.testing.assert_allclose(diff, 0.3, atol=1e-3)


def test_roller_pitch_is_a_full_pitch():
    v = var.roller_pitch(6)
    assert (v.low, v.high, v.unit) == (0.0, 2 * math.pi / 6, "rad")
    with pytest.raises(ValueError, match="rollers"):
        var.roller_pitch(0)
