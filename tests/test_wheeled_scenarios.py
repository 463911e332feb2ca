"""Each caster robot tracks its analytic model on one short scenario."""

import dataclasses

import mujoco
import numpy as np
import pytest

from wmr_mujoco import wheeled_scenarios as ws

#: One scenario per robot, cut to 3 s: the turning ones (arc, crab, ±0.3 rad turn).
SHORT = {("diffdrive", "arc"), ("single_steer", "crab 0.5 rad"),
         ("double_steer", "turn ±0.3 rad")}


@pytest.mark.parametrize("key", sorted(SHORT))
def test_short_scenario_meets_its_targets(key):
    s = next(s for s in ws.SCENARIOS if (s.robot, s.name) == key)
    meas = ws.measure(dataclasses.replace(s, duration=3.0))
    judged = {(n, v, t) for n, v, _, t, _ in meas.metrics if t is not None}
    assert len(judged) >= 3
    for name, value, target in judged:
        assert np.isfinite(value) and abs(value) <= target, (name, value, target)
    # The physics moved: the analytic path is at least 1 m.
    assert dict((n, v) for n, v, *_ in meas.metrics)["path"] > 1.0


@pytest.mark.parametrize("robot", ws.ROBOTS)
def test_controls_follow_the_actuator_order(robot):
    adapter = ws.make_adapter(robot)
    model = ws.load(robot)
    names = [model.actuator(i).name for i in range(model.nu)]
    expected = {"diffdrive": ["left_wheel", "right_wheel"],
                "single_steer": ["drive_wheel", "drive_steer"],
                "double_steer": ["front_wheel", "front_steer", "rear_wheel", "rear_steer"]}
    assert names == expected[robot]
    n_in = len(next(s for s in ws.SCENARIOS if s.robot == robot).inputs)
    ctrl = adapter.controls(np.full(n_in, 0.1), np.zeros(len(adapter.state_names)))
    assert ctrl.shape == (model.nu,)


def test_scenarios_cover_the_issue_list():
    names = {s.name for s in ws.scenarios_for("diffdrive")}
    assert {"straight", "arc", "spin in place", "figure eight"} <= names
    assert len(ws.scenarios_for("single_steer")) >= 3
    assert len(ws.scenarios_for("double_steer")) >= 3


def test_unknown_robot_is_a_clear_error():
    with pytest.raises(ValueError, match="valid robots are: diffdrive"):
        ws.scenarios_for("hovercraft")


def test_sim_state_reads_the_settled_robot_at_rest():
    model = ws.load("single_steer")
    data = mujoco.MjData(model)
    for _ in range(100):
        mujoco.mj_step(model, data)
    x = ws.make_adapter("single_steer").sim_state(model, data)
    # At rest: heading, steering angle and momentum are (numerically) zero.
    assert np.abs(x[2:]) == pytest.approx(np.zeros(3), abs=1e-6)
