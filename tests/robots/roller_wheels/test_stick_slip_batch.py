"""Step responses marched together are, to the bit, the responses marched one at a time."""

import dataclasses

import numpy as np
import pytest

from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels import roller_stick_slip as rss
from wmr_mujoco.robots.roller_wheels.stick_slip_batch import march_many
from wmr_mujoco.robots.roller_wheels.stick_slip_steps import march

BoxLcp, step_response, step_responses = rss.BoxLcp, rss.step_response, rss.step_responses
#: A mecanum platform (test_stick_slip_steps' numbers): mass, inertias, servo, contact.
LAY = ok.mecanum_layout(0.05, 0.15, 0.12)
H = ok.wheel_jacobian(LAY)
NUMBERS = {"mass": 4.0, "yaw_inertia": 0.08, "wheel_inertia": 0.004, "servo_gain": 2.0,
           "torque_limit": 3.0, "friction": 0.8, "com_height": 0.05}


def platform(layout=LAY, **kw):
    return rss.RollerPlatform(layout, **{**NUMBERS, **kw})


# The cases of test_stick_slip_steps (slip along x: every contact at its bound; a
# diagonal: two wheels idle; a turn with load transfer: slip, then stick; a servo held
# at its torque limit; friction out of reach), each on its own platform, plus runs whose
# platforms differ in their rows (other roller angles), so that every run of a batch
# has its own matrices, contact states and stopping step.
CASES = [((0.3, 0.0, 0.0), {}), ((0.25, 0.25, 0.0), {}), ((0.2, -0.1, 1.0), {}),
         ((1.5, 0.0, 0.0), {"torque_limit": 0.05}), ((0.3, 0.0, 0.0), {"friction": 1e6}),
         ((0.0, 0.0, 1.2), {"layout": dataclasses.replace(
             LAY, roller_angles=LAY.roller_angles * 0.9)}),
         ((0.3, -0.3, 0.0), {"layout": dataclasses.replace(
             LAY, roller_angles=LAY.roller_angles * 1.1)})]


def _runs():
    platforms = [platform(**kw) for _, kw in CASES]
    return platforms, [H @ np.array(t) for t, _ in CASES]


def test_march_many_is_march_of_each_run_bit_for_bit():
    platforms, cmds = _runs()
    total, chunk = 3000, 500  # 0.3 s in chunks of 50 ms: some runs stop early, some not
    got = march_many(platforms, [BoxLcp(p.delassus) for p in platforms], cmds, total, chunk,
                     1e-4, 1e-9)
    lengths = set()
    for p, cmd, rows in zip(platforms, cmds, got, strict=True):
        want = march(p, BoxLcp(p.delassus), cmd, total, chunk, 1e-4, 1e-9)
        lengths.add(len(want["time"]))
        assert rows is not None
        np.testing.assert_array_equal(rows["time"], want["time"])
        for key in ("q", "p", "loads", "dissipated"):
            assert rows[key].tobytes() == np.asarray(want[key]).tobytes(), key
        assert [tuple(s) for s in rows["state"].tolist()] == want["state"]
    assert len(lengths) > 1  # the runs stop at different steps (each its own settle)


def test_step_responses_are_step_response_bit_for_bit():
    platforms, cmds = _runs()
    got = step_responses(platforms, cmds, 0.5)
    for p, cmd, response in zip(platforms, cmds, got, strict=True):
        want = step_response(p, cmd, 0.5)
        for field in dataclasses.fields(want):
            a, b = getattr(response, field.name), getattr(want, field.name)
            assert a.shape == b.shape and a.tobytes() == b.tobytes(), field.name


def test_a_diverging_run_is_left_out_and_the_others_go_on():
    # A NaN command (step_response refuses it up front; march itself raises at the first
    # step): in a batch that run comes back as None and the other run is untouched.
    p = platform()
    cmds = [np.array([np.nan, 0.0, 0.0, 0.0]), H @ np.array([0.3, 0.0, 0.0])]
    got = march_many([p, p], [BoxLcp(p.delassus), BoxLcp(p.delassus)], cmds, 2000, 500,
                     1e-4, 1e-9)
    assert got[0] is None
    want = march(p, BoxLcp(p.delassus), cmds[1], 2000, 500, 1e-4, 1e-9)
    assert got[1]["q"].tobytes() == np.asarray(want["q"]).tobytes()
    with pytest.raises(ValueError, match="diverged"):
        march(p, BoxLcp(p.delassus), cmds[0], 2000, 500, 1e-4, 1e-9)


def test_bad_batches_are_refused_before_any_work():
    p = platform()
    cmd = H @ np.array([0.3, 0.0, 0.0])
    with pytest.raises(ValueError, match="one command per platform"):
        step_responses([p, p], [cmd], 0.2)
    with pytest.raises(ValueError, match="duration"):
        step_responses([p], [cmd], -1.0)
    with pytest.raises(ValueError, match="commanded"):
        step_responses([p], [np.zeros(3)], 0.2)
    three = platform(layout=ok.symmetric_layout(0.05, 0.15, 3), com_height=0.0)
    with pytest.raises(ValueError, match="same number of wheels"):
        march_many([p, three], [BoxLcp(p.delassus), BoxLcp(three.delassus)],
                   [cmd, np.zeros(3)], 10, 10, 1e-4, 1e-9)
    assert step_responses([], [], 0.2) == []
