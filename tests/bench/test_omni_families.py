"""The omni3 family table: rows per judged figure, worst and median over the draws."""

import pytest

from wmr_mujoco.bench import omni_families as of
from wmr_mujoco.robots import omni3
from wmr_mujoco.validation.metrics import Metric, Target
from wmr_mujoco.validation.scenarios import MeasurementResult, ScenarioKind

TARGET = Target.requirement(5.0, "test")


def test_table_reports_median_worst_and_the_worst_draw():
    sc = omni3.SPEC.scenario("slip onset")
    results = [(sc.member({"phase": p}), MeasurementResult(
        [Metric("f", v, "%", TARGET), Metric("reported", 99.0, "%")], []))
        for p, v in ((1.0, 2.0), (2.0, -7.0), (3.0, 4.0))]
    (row,) = of.table(results)
    assert (row["n"], row["median"], row["worst"], row["met"]) == (3, 4.0, 7.0, 2)
    assert row["worst draw"] == "phase=2"
    assert "| slip onset | f | 4 | 7 | 5 | 2/3 | phase=2 |" in of.markdown([(0, False, 1.0,
                                                                               [row])])


def test_family_members_are_the_seeded_draws():
    members = of.family_members(0, draws=2)
    # Measurement scenarios only: omni3's kinematic scenarios now carry the closed-loop
    # families every drivable robot gets, which this table does not run.
    measured = [s for s in omni3.SPEC.scenarios
                if s.kind is ScenarioKind.MEASUREMENT and s.family is not None]
    assert len(members) == 2 * len(measured)
    assert members == of.family_members(0, draws=2) != of.family_members(1, draws=2)


@pytest.mark.parametrize("argv", [["--seed", "-1"], ["--draws", "0"]])
def test_bad_arguments_exit_2(argv):
    with pytest.raises(SystemExit) as err:
        of.main(argv)
    assert err.value.code == 2
