"""The families in the report: spread table, quick label, members kept through the JSON."""

import dataclasses
import json

import pytest

from wmr_mujoco.robots import ROBOTS, get_spec
from wmr_mujoco.validation.family import Family, Vary
from wmr_mujoco.validation.family_report import (
    families_markdown,
    is_quick,
    quick_label,
    spread_text,
)
from wmr_mujoco.validation.members import run_family
from wmr_mujoco.validation.metrics import Metric
from wmr_mujoco.validation.report import merge_results, summary_line, write_report
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario, ScenarioKind
from wmr_mujoco.validation.targets import Target


def _measured(scenario, params):
    x = scenario.value("x", 0.5)
    return MeasurementResult([Metric("figure", x, "1", Target.requirement(1.0, "asked")),
                              Metric("hard", 2 * x, "1", Target.open(1.0, "asked", "why"))])


@pytest.fixture(scope="module")
def result():
    s = Scenario("disc", "sliding wheel", kind=ScenarioKind.MEASUREMENT, evaluate=_measured,
                 family=Family((Vary("x", 0.1, 0.9),), 6))
    return run_family(get_spec("disc"), s, seed=5, draws=4)


def test_the_spread_table_and_the_quick_label(result):
    assert is_quick(result)  # 4 of the 6 declared draws
    assert quick_label([result]).startswith("quick: 4 draws")
    text = spread_text([result])
    assert "figure" in text and " 4 " in text and "open" in text
    assert "quick" in families_markdown([result]) and "| 5 |" in families_markdown([result])
    line = summary_line([result])
    assert "1 targets open" in line and "disc/sliding wheel: hard" in line and "quick" in line


def test_members_survive_the_json_report(result, tmp_path):
    write_report([result], tmp_path, robots={"disc": ROBOTS["disc"]})
    doc = json.loads((tmp_path / "validation.json").read_text())
    assert doc["quick"] is True
    # Read back (as a later partial run merges it): the members and their figures.
    spec = ROBOTS["disc"]
    robots = {"disc": dataclasses.replace(spec, scenarios=(result.scenario,), demo_scenario=None,
                                          bench_scenario=None, render_scenario=None,
                                          clips=())}
    (back,) = merge_results([], robots, tmp_path)
    assert [m.scenario.draw for m in back.members] == [m.scenario.draw for m in result.members]
    assert [m.rows[0].value for m in back.members] == [m.rows[0].value for m in result.members]
    assert back.seed == 5 and (tmp_path / "validation" / "disc" / "spread.png").is_file()
