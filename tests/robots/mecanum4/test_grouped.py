"""Grouped kinematic runs: the same metrics as the runs alone, named by member."""

import dataclasses

import pytest

from wmr_mujoco.robots.mecanum4 import SPEC, kinematic_runs
from wmr_mujoco.robots.mecanum4.grouped import evaluate_group
from wmr_mujoco.validation.runner import run_scenario


def test_group_metrics_equal_the_runs_alone():
    # One batched rollout gives each trajectory bit for bit (sim.engine.simulate_batch),
    # so every judged metric equals the member's own run through the runner.
    members = [dataclasses.replace(s, duration=0.6) for s in kinematic_runs()
               if s.name in ("translate 0° (ramp)", "translate 90° (step)")]
    res = evaluate_group(members, None)
    assert [s.label for s in res.series] == [m.name for m in members]
    got = {m.name: m for m in res.metrics}
    for member in members:
        alone = run_scenario(SPEC, member)
        for row in alone.rows:
            if row.target is None:
                continue
            m = got[f"{member.name}: {row.metric}"]
            assert m.value == pytest.approx(row.value, rel=1e-9, abs=1e-12)
            assert m.target.value == pytest.approx(row.target)


def test_spec_groups_the_eight_translations():
    group = SPEC.scenario("8 translations (ramp)")
    assert len(group.evaluate.members) == 8
    assert {s.duration for s in group.evaluate.members} == {2.0}


def test_a_member_of_the_group_passes_its_draw_to_every_run(monkeypatch):
    """A member of the group's family runs the eight translations with its draw."""
    from wmr_mujoco.robots.mecanum4 import SPEC as MECANUM
    from wmr_mujoco.robots.mecanum4 import grouped

    seen = []
    monkeypatch.setattr(grouped, "evaluate_group", lambda runs, params: seen.append(runs))
    group = MECANUM.scenario("8 translations (ramp)")
    member = group.members(0, draws=1)[0]
    member.evaluate(member, None)
    assert len(seen[0]) == 8 and all(r.draw == member.draw for r in seen[0])
    group.evaluate(group, None)  # the nominal group runs the nominal translations
    assert all(not r.draw for r in seen[1])
