"""The (1,2) robot's registry entry: actuator order, one ICR for both wheel speeds."""

import dataclasses
import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.robots import double_steer, get_spec
from wmr_mujoco.robots.double_steer.params import DoubleSteerParams
from wmr_mujoco.validation import floor_family as ff


def _adapter(model):
    return double_steer.kinematic_adapter(double_steer.SCENARIOS[0], model, None)


def test_controls_follow_the_actuator_order_and_share_one_icr():
    model = load("double_steer")
    assert [model.actuator(i).name for i in range(model.nu)] == [
        "front_wheel", "front_steer", "rear_wheel", "rear_steer"]
    p = DoubleSteerParams()
    b1, b2, v1 = 0.4, -0.2, 0.3
    ctrl = _adapter(model).controls(np.array([v1, 0.1, -0.1]), np.array([0, 0, 0, b1, b2]))
    r = p.wheel.radius
    v2 = ctrl[2] * r
    # Rigid chassis: both contact points have the same velocity component along the
    # line joining them (the body x axis): v₁ cos β₁ = v₂ cos β₂.
    assert v1 * math.cos(b1) == pytest.approx(v2 * math.cos(b2), rel=1e-12)
    assert ctrl[[0, 1, 3]] == pytest.approx([v1 / r, 0.1, -0.1])


def test_sim_state_reads_pose_and_steering_at_rest():
    model = load("double_steer")
    data = mujoco.MjData(model)
    for _ in range(100):
        mujoco.mj_step(model, data)
    x = _adapter(model).sim_state(model, data)
    assert np.abs(x[2:]) == pytest.approx(np.zeros(3), abs=1e-6)


# The random-steps draw that rolled the robot over at seed 3 (member 12), written out so
# that the test does not depend on the family's sampling.
_ROLLING_DRAW = {ff.WHEEL_PHASE: 0.3081833791135091, ff.INPUTS: 0.4553005907582337}
#: Its roll starts after 4.6 s (chassis tilt beyond 5°); the first 4.5 s are upright.
_UPRIGHT_PART = 4.5


def _random_steps():
    spec = get_spec("double_steer")
    return spec, spec.scenario(ff.NAME)


def test_random_steps_open_only_what_a_roll_over_misses():
    spec, s = _random_steps()
    assert set(s.open_targets) == {ff.OVER_RUN, ff.DEPTH}  # the step-from-rest stays judged
    rows = {m.name: m for m in ff.measure(spec, s.member(_ROLLING_DRAW)).metrics}
    # what the roll-over misses is what was opened: both figures beyond their targets
    for name in (ff.OVER_RUN, ff.DEPTH):
        assert abs(rows[name].value) > rows[name].target.value, name


def test_a_draw_that_rolls_over_presses_deeper_only_after_the_roll():
    # The depth requirement (0.5 mm, issue 24 § 3) is missed by the landing of a robot
    # that rolled over, not by its driving: the same draw cut before the roll stays
    # upright (tilt a few degrees at most: 10° is far below the tip-over) and within it;
    # the whole draw ends upside down (tilt beyond 90°) and beyond it.
    spec, s = _random_steps()
    member = s.member(_ROLLING_DRAW)
    reading, tilt = ff.run(spec, dataclasses.replace(member, duration=_UPRIGHT_PART))
    assert tilt < 10.0
    assert 1e3 * reading.max_depth <= ff.DEPTH_TARGET.value
    reading, tilt = ff.run(spec, member)
    assert tilt > 90.0
    assert 1e3 * reading.max_depth > ff.DEPTH_TARGET.value


def test_random_steps_that_stay_upright_keep_the_depth_bound():
    # The opened depth target still holds for every draw of the seed that does not roll
    # over (tilt below 90°; the draws that stay on their wheels tilt by tens of degrees
    # at most): the bound is missed only by the landing after a roll.
    spec, s = _random_steps()
    upright = 0
    for member in s.members(3):
        reading, tilt = ff.run(spec, member)
        if tilt < 90.0:
            upright += 1
            assert 1e3 * reading.max_depth <= ff.DEPTH_TARGET.value, member.draw
    assert upright >= s.family.draws - 1  # one draw of this seed rolls over
