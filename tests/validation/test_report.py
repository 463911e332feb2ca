import json

import pytest

from wmr_mujoco.robots import ROBOTS, get_spec
from wmr_mujoco.validation.report import slug, text_table, write_report
from wmr_mujoco.validation.runner import run_all
from wmr_mujoco.validation.scenarios import Scenario
from wmr_mujoco.validation.signals import Piecewise, const


@pytest.fixture(scope="module")
def results():
    disc = get_spec("disc")
    return run_all([
        # 2 s, as in test_runner: the ramp's start-up lag a small share of the path
        (disc, Scenario("disc", "short", (const(1.0, 0.5), const(0.0)), duration=2.0)),
        # const refuses NaN; a signal that yields one mid-run still must become a failed row.
        (disc, Scenario("disc", "nan input", (Piecewise(((0.0, float("nan")),)), const(0.0)),
                        duration=0.1)),
    ])


def test_report_files(results, tmp_path):
    path = write_report(results, tmp_path, robots=ROBOTS)
    text = path.read_text()
    assert "1 of 2 scenarios pass" in text and "disc/nan input" in text
    doc = json.loads((tmp_path / "validation.json").read_text())
    assert doc["passed"] is False and len(doc["scenarios"]) == 2
    assert (tmp_path / "validation" / "disc" / "short.png").stat().st_size > 1000
    assert not list(tmp_path.rglob(".*"))  # no temporary files left


def test_failed_report_write_leaves_no_file(results, tmp_path, monkeypatch):
    import wmr_mujoco.validation.report as rep

    def boom(_results):
        raise RuntimeError("disk full")

    monkeypatch.setattr(rep, "markdown_table", boom)
    with pytest.raises(RuntimeError):
        write_report(results, tmp_path, robots=ROBOTS)
    assert not (tmp_path / "validation.md").exists()
    assert not list(tmp_path.glob(".*"))


def test_text_table_and_slug(results):
    table = text_table(results)
    assert table.splitlines()[0].split()[:3] == ["robot", "scenario", "metric"]
    assert "FAIL" in table
    assert slug("omni3/translate 45°") == "omni3-translate-45deg"


def test_markdown_cells_escape_pipes():
    from wmr_mujoco.validation.metrics import Metric, Row, Target, Trace
    from wmr_mujoco.validation.report import markdown_table
    from wmr_mujoco.validation.runner import ScenarioResult

    s = Scenario("disc", "s", (const(1.0),))
    row = Row.of("disc", "s", Metric("m", 1.0, "", Target.derived(2.0, "|F| ≤ μN"), "|x|"))
    line = markdown_table([ScenarioResult(s, [row], Trace())]).splitlines()[-1]
    assert line.count(" | ") + 2 == 9 and "\\|F\\|" in line and "\\|x\\|" in line


def test_summary_line_counts_open_targets():
    """Open rows are counted beside the verdict and do not fail a scenario."""
    from wmr_mujoco.validation.metrics import Metric, Row, Target, Trace
    from wmr_mujoco.validation.report import summary_line
    from wmr_mujoco.validation.runner import ScenarioResult

    s = Scenario("omni3", "x", (const(0.0),), duration=0.1)
    rows = [Row.of("omni3", "x", Metric("a", 2.0, "%", Target.open(1.0, "i", "why"))),
            Row.of("omni3", "x", Metric("b", 0.5, "%", Target.requirement(1.0, "i")))]
    res = ScenarioResult(s, rows, Trace())
    assert res.passed
    assert summary_line([res]) == ("1 of 1 scenarios pass; 1 targets open (shown with "
                                   "their figures, not judged): omni3/x: a")
    assert "open" in text_table([res], judged_only=True)


def test_summary_headline_is_a_judged_row_and_the_verdict_counts_open_ones():
    """An open row comes first here; the headline must still be the judged one."""
    from wmr_mujoco.validation.metrics import Metric, Row, Target, Trace
    from wmr_mujoco.validation.report import summary_table
    from wmr_mujoco.validation.runner import ScenarioResult

    s = Scenario("omni3", "x", (const(0.0),), duration=0.1)
    rows = [Row.of("omni3", "x", Metric("open one", 2.0, "%", Target.open(1.0, "i", "why"))),
            Row.of("omni3", "x", Metric("judged one", 0.5, "%", Target.requirement(1.0, "i")))]
    line = summary_table([ScenarioResult(s, rows, Trace())]).splitlines()[-1]
    assert "judged one: 0.5 %" in line and "open one" not in line
    assert line.endswith("| pass (1 open) |")


def test_summary_headline_escapes_pipes():
    from wmr_mujoco.validation.metrics import Metric, Row, Target, Trace
    from wmr_mujoco.validation.report import summary_table
    from wmr_mujoco.validation.runner import ScenarioResult

    s = Scenario("disc", "s", (const(1.0),))
    row = Row.of("disc", "s", Metric("|a − b|", 1.0, "m", Target.derived(2.0, "x")))
    line = summary_table([ScenarioResult(s, [row], Trace())]).splitlines()[-1]
    assert line.count(" | ") + 2 == 11 and "\\|a − b\\|" in line


def _result(robot, name, value, passed=True):
    """A judged result of a registered scenario, made by hand (no simulation)."""
    from wmr_mujoco.robots import get_spec
    from wmr_mujoco.validation.metrics import Row, Trace
    from wmr_mujoco.validation.runner import ScenarioResult

    row = Row(robot, name, "worst position error", value, "% of path", 0.5, passed, "", "req")
    return ScenarioResult(get_spec(robot).scenario(name), [row], Trace())


def _every_result(value):
    from wmr_mujoco.robots import ROBOTS

    return [_result(spec.name, s.name, value) for spec in ROBOTS.values()
            for s in spec.scenarios]


def test_a_partial_run_is_merged_into_the_full_report(tmp_path):
    full = _every_result(0.1)
    write_report(full, tmp_path, robots=ROBOTS)
    assert json.loads((tmp_path / "validation.json").read_text())["complete"] is True
    write_report([_result("omni3", "rotate", 0.3)], tmp_path, robots=ROBOTS)
    doc = json.loads((tmp_path / "validation.json").read_text())
    assert doc["complete"] is True and len(doc["scenarios"]) == len(full)
    values = {(r["robot"], r["scenario"]): r["metrics"][0]["value"] for r in doc["scenarios"]}
    assert values[("omni3", "rotate")] == 0.3 and values[("disc", "straight")] == 0.1
    # Registry order is kept, whatever the order of the runs.
    assert [(r["robot"], r["scenario"]) for r in doc["scenarios"]] == [
        (r.scenario.robot, r.scenario.name) for r in full]
    summary = (tmp_path / "summary.md").read_text()
    assert summary.count("\n") == len(full) + 2 and "| disc | straight |" in summary


def test_a_first_partial_run_says_what_is_missing(tmp_path):
    write_report([_result("disc", "straight", 0.1)], tmp_path, robots=ROBOTS)
    doc = json.loads((tmp_path / "validation.json").read_text())
    assert doc["complete"] is False and "omni3/rotate" in doc["missing"]
    assert "Not run yet: " in (tmp_path / "validation.md").read_text()


def test_a_run_removes_its_own_stale_plots_only(tmp_path):
    plots = tmp_path / "validation"
    for robot in ("disc", "omni3"):
        (plots / robot).mkdir(parents=True)
        (plots / robot / "renamed-scenario.png").write_bytes(b"png")
    write_report([_result("disc", "straight", 0.1)], tmp_path, robots=ROBOTS)
    assert not (plots / "disc" / "renamed-scenario.png").exists()
    assert (plots / "omni3" / "renamed-scenario.png").exists()


def test_a_corrupt_earlier_report_counts_as_none(tmp_path):
    (tmp_path / "validation.json").write_text("{not json")
    write_report([_result("disc", "straight", 0.1)], tmp_path, robots=ROBOTS)
    doc = json.loads((tmp_path / "validation.json").read_text())
    assert [r["scenario"] for r in doc["scenarios"]] == ["straight"]


@pytest.mark.parametrize("make, match", [
    (lambda p: (p / "f").write_text("x") and p / "f", "is a file; give a folder"),
    (lambda p: p / "missing" / "dir", "folder .*missing' does not exist; create it first"),
])
def test_report_folder_is_checked_before_any_work(tmp_path, make, match):
    from wmr_mujoco.validation.report import check_report_folder

    with pytest.raises(ValueError, match=match):
        check_report_folder(make(tmp_path))
    assert check_report_folder(tmp_path / "new") == tmp_path / "new"


def test_a_grouped_scenario_headlines_its_worst_member():
    """mecanum4's ``8 translations (step)``: the rows are per member; the summary shows
    the member nearest its target (45° here), never simply the first (0°)."""
    from wmr_mujoco.validation.metrics import Metric, Row, Target, Trace
    from wmr_mujoco.validation.report import summary_table
    from wmr_mujoco.validation.runner import ScenarioResult

    s = Scenario("mecanum4", "8 translations (step)", (const(0.0),), duration=0.1)
    req = Target.requirement(1.0, "r")
    rows = [Row.of("mecanum4", s.name, Metric(f"translate {a}°: worst position error", v,
                                              "% of path", req))
            for a, v in ((0, 0.08457), (45, 0.7476), (90, 0.1))]
    rows.append(Row.of("mecanum4", s.name, Metric("translate 45°: worst heading error", 0.9,
                                                  "deg", Target.requirement(1.0, "r"))))
    line = summary_table([ScenarioResult(s, rows, Trace())]).splitlines()[-1]
    assert "| translate 45°: worst position error: 0.7476 % of path |" in line
    assert "| 0.7476 % |" in line  # the worst-position column: the same worst member
    assert "| 0.9° |" in line      # the worst-heading column: its one member


def test_a_dimensionless_value_prints_no_unit():
    """``0.7686 1 ... ≤ 1 1`` read as two numbers; a ratio shows bare."""
    from wmr_mujoco.validation.metrics import Metric, Row, Target, Trace
    from wmr_mujoco.validation.report import markdown_table, summary_table
    from wmr_mujoco.validation.runner import ScenarioResult

    s = Scenario("whipple", "w", (const(0.0),), duration=0.1)
    row = Row.of("whipple", "w", Metric("lean ratio", 0.7686, "1",
                                        Target.requirement(1.0, "decays")))
    res = [ScenarioResult(s, [row], Trace())]
    assert text_table(res).splitlines()[-1].split()[4:8] == ["0.7686", "≤", "1", "pass"]
    assert "| lean ratio | 0.7686 | ≤ 1 |" in markdown_table(res)
    assert "| lean ratio: 0.7686 |" in summary_table(res)


def test_no_basis_of_a_target_cites_an_internal_issue_number():
    """The report's basis column is read by people outside the project: it says what is
    asked and why ("issue 16" means nothing to them)."""
    import importlib
    import pkgutil
    import re

    import wmr_mujoco.robots as robots
    from wmr_mujoco.validation.metrics import Target

    labels = {t.label for spec in robots.ROBOTS.values() for t in spec.targets.values()}
    for info in pkgutil.walk_packages(robots.__path__, "wmr_mujoco.robots."):
        module = vars(importlib.import_module(info.name))  # module-level targets too
        labels |= {t.label for t in module.values() if isinstance(t, Target)}
        labels |= {str(v) for k, v in module.items() if k == "SOURCE"}
    assert len(labels) > 20
    assert not [x for x in labels if re.search(r"\bissues? \d", x)]
