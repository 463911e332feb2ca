import pytest

from wmr_mujoco.validation.metrics import Metric, Series
from wmr_mujoco.validation.scenarios import (
    MeasurementResult,
    Scenario,
    ScenarioKind,
    scenarios_for,
)
from wmr_mujoco.validation.signals import const


def test_every_robot_has_its_scenarios():
    scenarios = scenarios_for()
    names = {s.key for s in scenarios}
    assert len(names) == len(scenarios), "scenario names must be unique per robot"
    # The robots validated since the first release keep their scenarios; every robot added
    # since brings its own (the registry test checks a spec's scenarios belong to it).
    assert {s.robot for s in scenarios} >= {"disc", "bicycle", "tricycle", "omni3"}
    assert "disc" in {s.robot for s in scenarios if s.kind is ScenarioKind.DYNAMIC}
    # omni3's torque inputs are judged against its hybrid model (measurement scenarios).
    assert {s.name for s in scenarios if s.robot == "omni3"
            and s.kind is ScenarioKind.MEASUREMENT} >= {"torque along x", "slip onset"}
    assert sum(s.name.startswith("translate ") for s in scenarios) == 8


def test_selection_and_bad_robot():
    assert all(s.robot == "bicycle" for s in scenarios_for(["bicycle"]))
    with pytest.raises(ValueError, match="no validation scenarios for robot 'disc_free'"):
        scenarios_for(["disc_free"])
    with pytest.raises(ValueError, match="unknown robot 'tank'"):
        scenarios_for(["tank"])


def test_kind_from_its_string_and_bad_kind():
    assert Scenario("disc", "a", (const(1.0),), kind="dynamic").kind is ScenarioKind.DYNAMIC
    with pytest.raises(ValueError, match="unknown scenario kind 'static'; valid scenario "
                                         "kinds are: kinematic, dynamic, measurement"):
        Scenario("disc", "a", kind="static")


def test_measurement_scenarios_carry_their_evaluate():
    def evaluate(scenario, params):
        return MeasurementResult([Metric("x", 1.0, "m")], [Series("x", [0, 1], [0, 1])])

    s = Scenario("disc", "m", kind=ScenarioKind.MEASUREMENT, evaluate=evaluate)
    assert s.evaluate(s, None).metrics[0].value == 1.0
    with pytest.raises(ValueError, match="needs evaluate"):
        Scenario("disc", "m", kind=ScenarioKind.MEASUREMENT)
    with pytest.raises(ValueError, match="takes no evaluate"):
        Scenario("disc", "k", (const(1.0),), evaluate=evaluate)


def test_only_a_measurement_takes_a_start_state():
    def start(model, data, params):
        data.qvel[0] = 1.0

    s = Scenario("disc", "m", kind=ScenarioKind.MEASUREMENT, start=start,
                 evaluate=lambda sc, p: MeasurementResult([]))
    assert s.start is start
    with pytest.raises(ValueError, match="disc/k: only a measurement scenario takes a start "
                                         "state"):
        Scenario("disc", "k", (const(1.0),), start=start)


@pytest.mark.parametrize(("field", "value"), [("duration", 0.0), ("settle", -1.0)])
def test_bad_times_are_refused(field, value):
    with pytest.raises(ValueError, match=f"disc/a: {field} = "):
        Scenario("disc", "a", (const(1.0),), **{field: value})
