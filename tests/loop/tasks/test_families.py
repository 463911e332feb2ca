"""The closed-loop scenario families: which robots get which, and one member of each kind.

Each member test runs the physics; tolerances are the scenarios' own targets (the
issue's requirements, the robot's open-loop fidelity) or derived beside the assertion.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from wmr_mujoco.loop.tasks import bracket, families, upright
from wmr_mujoco.robots import ROBOTS
from wmr_mujoco.validation.judges import POSITION_PCT


def metrics(scenario, draw=None):
    s = scenario if draw is None else scenario.member(draw)
    return {m.name: m for m in s.evaluate(s, None).metrics}


def test_the_command_kind_picks_the_tasks_not_the_name() -> None:
    # The same entry under another name gets the same scenarios (nothing reads the name).
    for name, spec in ROBOTS.items():
        twin = dataclasses.replace(spec, name=f"{name}_twin", scenarios=(), clips=(),
                                   demo_scenario=None, bench_scenario=None,
                                   render_scenario=None, prepared_together=())
        ours = [s.name for s in families.loop_scenarios(spec)]
        assert [s.name for s in families.loop_scenarios(twin)] == ours


def test_the_registry_adds_the_families_with_their_draws() -> None:
    names = {n: [s.name for s in ROBOTS[n].scenarios] for n in ROBOTS}
    assert families.BRACKET_NAME in names["diffdrive"]
    assert families.BRACKET_NAME in names["disc"]
    assert families.tracking_name("holonomic", "figure_eight") in names["omni3"]
    assert families.tracking_name("stanley", "lane_change") in names["bicycle"]
    assert [families.upright_name(v) for v in (3.0, 2.0)] == [
        n for n in names["whipple"] if n.startswith("upright")]
    for spec in ROBOTS.values():
        for s in families.loop_scenarios(spec):
            # 20 draws, or the kinematic families' number for a tracking family (a
            # kinematic controller's claim whose spread is small: family_spread shows it).
            tracking = s.name.startswith("closed loop:")
            assert s.family is not None
            assert s.family.draws >= (families.TRACKING_DRAWS if tracking else 20)
            assert "/" not in s.name  # a key is robot/scenario


def test_a_car_without_a_wheelbase_and_an_unknown_command_kind_get_none() -> None:
    # single_steer's parameters have no wheelbase (no car law can be built); double_steer's
    # (v, front_steer, rear_steer) is of no controller's kind; disc_free has no actuators.
    for name in ("single_steer", "double_steer", "disc_free"):
        assert families.loop_scenarios(ROBOTS[name]) == ()


def test_tracking_targets_are_the_open_loop_fidelity() -> None:
    for spec in ROBOTS.values():
        for s in families.loop_scenarios(spec):
            if s.name.startswith("closed loop"):
                t = families.open_loop_target(spec)
                assert t is not None and t.value == spec.targets[POSITION_PCT].value
                assert t.kind == "derived bound"


def test_a_tracking_member_on_the_physics_meets_its_bound() -> None:
    spec = ROBOTS["diffdrive"]
    s = spec.scenario(families.tracking_name("kanayama", "lane_change"))
    draw = s.family.sample(0, s.key)[0]
    got = metrics(s, draw)
    m = got["cross-track excess, physics over model"]
    assert abs(m.value) <= m.target.value
    assert got["physics-model deviation"].target is None  # along-track lag: reported
    # The drawn start is off the path: both runs had a start error of at least its
    # lateral offset (cross-track at t = 0), and the physics' worst is within the
    # deviation of the model's (the cross-track error is 1-Lipschitz in the position).
    assert got["worst cross-track, model"].value >= abs(draw["lateral"]) - 1e-9
    dev_m = got["physics-model deviation"].value / 100 * got["path travelled"].value
    assert abs(got["worst cross-track, physics"].value
               - got["worst cross-track, model"].value) <= dev_m + 1e-9


def test_a_bracket_member_on_the_physics_and_the_kinematic_backend() -> None:
    s = ROBOTS["diffdrive"].scenario(families.BRACKET_NAME)
    draw = s.family.sample(0, s.key)[1]
    got = metrics(s, draw)
    eps = draw["eps"]
    assert got["net motion error, physics"].value <= 5.0  # the requirement
    # Kinematic backend: each segment's feedback leaves e^(−k T_extra) of its amount ε,
    # four segments at most 4 ε e^(−12) m off, over the exact step 2ε sin(ε/2) (twice
    # for the zero-order hold's rounding at the end of a segment).
    bound = 2 * 4 * eps * math.exp(-bracket.GAIN * bracket.SEGMENT_EXTRA) / (
        2 * eps * math.sin(eps / 2))
    assert got["net motion error, kinematic backend"].value <= 100 * bound
    # Second order: ε²[g₁, g₂] = (0, −ε²) in the start frame, against the exact step.
    exact = np.array([eps * (1 - math.cos(eps)), -eps * math.sin(eps)])
    second = np.array([0.0, -eps * eps])
    assert got["second-order prediction error"].value == pytest.approx(
        100 * np.linalg.norm(second - exact) / np.linalg.norm(exact), rel=1e-6)


def test_the_whipple_bicycle_stays_upright_and_falls_without_the_law() -> None:
    s = ROBOTS["whipple"].scenario(families.upright_name(2.0))
    got = metrics(s)  # the nominal member: 0.5 rad/s push at 2 m/s
    assert got["peak lean, physics"].value < ROBOTS["whipple"].command.balance.fallen
    assert got["upright time, physics"].value == pytest.approx(upright.DURATION)
    # Below the weave speed the uncontrolled bicycle falls well within the 10 s.
    assert got["upright time, torques 0"].value < upright.DURATION / 2
