"""omni3's measurement families: declared, drawn, run in one batch, read by evaluate."""

import math

import numpy as np
import pytest

from wmr_mujoco.robots import omni3
from wmr_mujoco.robots.omni3 import families, members
from wmr_mujoco.robots.omni3.dynamics import evaluate_torque
from wmr_mujoco.validation.scenarios import ScenarioKind


def test_every_measurement_scenario_is_a_family_of_at_least_20_draws():
    """Issue 24: each dynamic family has ≥ 20 draws and varies the wheels' start phase
    over a full roller pitch of a row (6 rollers: 60°)."""
    for sc in omni3.SPEC.scenarios:
        if sc.kind is ScenarioKind.MEASUREMENT:
            assert sc.family is not None and sc.family.draws >= 20, sc.name
            phase = {v.name: v for v in sc.family.vary}["phase"]
            assert (phase.low, phase.high) == (0.0, 60.0)
    g = omni3.runs.hybrid().rollers
    assert families.PITCH_DEG == pytest.approx(360.0 / (g.angles.size / 2))


def test_member_spec_applies_the_draw():
    """Phase in degrees → radians on every wheel; a scale multiplies the command; a coast
    takes speed, yaw rate, duration and ramp; the nominal member is the base run."""
    step = {s.name: s for s in omni3.DYNAMIC_SPECS}["step 45°"]
    sc = omni3.SPEC.scenario("step 45°")
    assert members.member_spec(sc, step) is step
    m = members.member_spec(sc.member({"phase": 30.0, "scale": 0.9}), step)
    assert m.phase == pytest.approx(math.pi / 6)
    np.testing.assert_allclose(m.command, 0.9 * np.asarray(step.command))
    coast = omni3.coasting.COAST_SPEC
    c = members.member_spec(omni3.SPEC.scenario(coast.name).member(
        {"phase": 0.0, "speed": 0.25, "yaw_rate": 1.1, "coast": 2.5, "ramp": 0.0}), coast)
    assert (c.lead_in, c.duration, c.lead_ramp) == ((0.25, 0.0, 1.1), 2.5, 0.0)


def test_prepared_members_are_evaluated_from_their_own_start():
    """Two members of a torque family prepared in one batch: each evaluate takes its run
    (the cache empties), whose wheels start at the member's phase (the rate servo holds
    them while the robot settles, to within a degree)."""
    sc = omni3.SPEC.scenario("torque rotate")
    pair = [sc.member({"phase": p, "scale": 1.0}) for p in (5.0, 40.0)]
    omni3.SPEC.prepare(pair, None)
    base = {s.name: s for s in omni3.DYNAMIC_SPECS}[sc.name]
    for m, phase in zip(pair, (5.0, 40.0), strict=True):
        run = members._READY[(members.member_spec(m, base), None)]
        np.testing.assert_allclose(np.degrees(run.wheel_angles[0]), phase, atol=1.0)
        rows = {x.name for x in evaluate_torque(m, None).metrics}
        assert "hybrid: worst r error" in rows
    assert not members._READY


def test_prepare_refuses_an_oversized_batch():
    base = omni3.DYNAMIC_SPECS[0]
    sc = omni3.SPEC.scenario(base.name)
    many = [members.member_spec(sc.member({"phase": 0.0, "scale": 0.8 + k * 1e-4}), base)
            for k in range(members.MAX_READY + 1)]
    with pytest.raises(ValueError, match="at most"):
        members.prepare(many, None)
