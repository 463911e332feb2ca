"""mecanum4 under torques through the runner: straight ahead judged, the rest reported."""

import dataclasses

import pytest

from wmr_mujoco.robots.mecanum4 import SPEC
from wmr_mujoco.robots.mecanum4.dynamics import JUDGED_PREFIX
from wmr_mujoco.validation.runner import run_scenario


def test_forward_torques_follow_the_reduced_equations():
    # Equal torques drive straight ahead, where no roller turns; requirement (issue 5,
    # omni3's): body velocity within 3 % of the reduced Lagrange model over the run.
    s = dataclasses.replace(SPEC.scenario(JUDGED_PREFIX), duration=1.0)
    res = run_scenario(s)
    judged = [r for r in res.rows if r.target is not None]
    assert len(judged) == 1 and judged[0].passed
    ratio = next(r.value for r in res.rows if r.metric == "final u: MuJoCo / Lagrange")
    assert ratio == pytest.approx(1.0, abs=0.03)


def test_mixed_torques_are_reported_not_judged():
    s = dataclasses.replace(SPEC.scenario("torque mixed"), duration=0.6)
    res = run_scenario(s)
    assert res.error is None
    assert all(r.target is None for r in res.rows)
