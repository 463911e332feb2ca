import pytest

from wmr_mujoco.scenarios import SCENARIOS, scenarios_for


def test_every_robot_has_its_scenarios():
    names = {s.key for s in SCENARIOS}
    assert len(names) == len(SCENARIOS), "scenario names must be unique per robot"
    assert {s.robot for s in SCENARIOS} == {"disc", "bicycle", "tricycle", "omni3"}
    assert {s.robot for s in SCENARIOS if s.kind == "dynamic"} == {"disc", "omni3"}
    assert sum(s.name.startswith("translate ") for s in SCENARIOS) == 8


def test_selection_and_bad_robot():
    assert all(s.robot == "bicycle" for s in scenarios_for(["bicycle"]))
    with pytest.raises(ValueError, match="no validation scenarios for robot 'disc_free'"):
        scenarios_for(["disc_free"])
