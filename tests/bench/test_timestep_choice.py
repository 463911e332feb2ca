"""Which longer steps keep every target: candidates, the early stop, the table."""

from __future__ import annotations

import math

import pytest

from wmr_mujoco.bench import timestep_choice
from wmr_mujoco.robots import get_spec
from wmr_mujoco.validation.targets import Row


def _row(scenario, value, passed):
    return Row("r", scenario, "m", value, "%", 1.0, passed)


class _Job:
    def __init__(self, name):
        self.name = name


def test_validation_stops_after_the_first_families_that_lose_a_target(monkeypatch, tmp_path):
    """Four families, two at a time: the second batch loses one, the third never runs;
    a complete pass is kept in the cache and read back without running."""
    spec = get_spec("diffdrive")
    names = ["a", "b", "c", "d"]
    monkeypatch.setattr(timestep_choice, "validation_jobs",
                        lambda robots: [(spec, _Job(n)) for n in names])
    monkeypatch.setattr(timestep_choice, "CACHE", tmp_path)
    ran = []
    bad = {"c"}

    def fake(spec_, key, seed, params):
        ran.append(names[key])
        return [_row(names[key], 2.0 if names[key] in bad else 0.5, names[key] not in bad)]

    monkeypatch.setattr(timestep_choice, "family_rows", fake)
    default = {(n, "m", "%"): _row(n, 0.5, True) for n in names}
    params = timestep_choice.at_step(spec, 0.0025).params
    f = timestep_choice.fidelity(spec, params, 0, default, jobs=1)
    assert f.lost == ("c / m (%)",) and (f.families, f.total) == (3, 4)
    assert ran == ["a", "b", "c"]
    assert "stopped after 3 of 4 families" in timestep_choice.verdict_text({0: f})
    ran.clear()
    assert timestep_choice.fidelity(spec, params, 0, default, jobs=1) == f
    assert ran == []  # the stop is kept too
    # ... for these jobs only: two at a time (in worker processes) the stop comes after
    # the batch (c, d), not the one-at-a-time stop's 3 families
    f2 = timestep_choice.fidelity(spec, params, 0, default, jobs=2)
    assert (f2.families, f2.lost) == (4, f.lost)
    # a stop this module did not write is run again, not trusted
    [stop] = [p for p in tmp_path.glob("*.j1.stopped.json")]
    stop.write_text("{not json")
    ran.clear()
    assert timestep_choice.fidelity(spec, params, 0, default, jobs=1) == f
    assert ran == ["a", "b", "c"]
    for kept_stop in tmp_path.glob("*.stopped.json"):
        kept_stop.unlink()

    bad.clear()
    ran.clear()
    f = timestep_choice.fidelity(spec, params, 0, default, jobs=1)
    assert not f.lost and ran == names
    ran.clear()
    assert not timestep_choice.fidelity(spec, params, 0, default, jobs=1).lost
    assert ran == []  # read from the cache


def test_a_family_that_produced_no_rows_counts_as_lost(monkeypatch, tmp_path):
    spec = get_spec("diffdrive")
    monkeypatch.setattr(timestep_choice, "validation_jobs",
                        lambda robots: [(spec, _Job("a")), (spec, _Job("b"))])
    monkeypatch.setattr(timestep_choice, "CACHE", tmp_path)
    monkeypatch.setattr(timestep_choice, "family_rows",
                        lambda s, k, seed, p: [] if k == 0 else [_row("b", 0.5, True)])
    default = {(n, "m", "%"): _row(n, 0.5, True) for n in "ab"}
    f = timestep_choice.fidelity(spec, timestep_choice.at_step(spec, 0.0025).params, 0,
                                 default, jobs=1)
    assert f.lost == ("a / m (%)",) and f.families == 1


def test_the_table_names_the_cheapest_step_that_keeps_every_target():
    rows = [
        {"robot": "x", "timestep": 0.002, "dampratio": 1.0, "rtf": 100.0, "ratio": 1.0,
         "verdict": "the default"},
        {"robot": "x", "timestep": 0.0025, "dampratio": 1.0, "rtf": 125.0, "ratio": 0.8,
         "verdict": "seed 0: passes every target", "acceptable": True},
        {"robot": "y", "timestep": 0.002, "dampratio": 1.0, "rtf": 100.0, "ratio": 1.0,
         "verdict": "the default"},
        {"robot": "y", "timestep": 0.005, "dampratio": 1.0, "rtf": math.nan,
         "ratio": math.nan, "verdict": "diverged on the timing drive", "acceptable": False},
    ]
    text = timestep_choice.table(rows, [0], timestep_choice.QUICK, quick=True)
    assert text.startswith("QUICK run")
    assert "| x | 2.5 ms | 1 | 125× | 0.80 | seed 0: passes every target |" in text
    assert ("- x: a longer step keeps every target the defaults meet: 2.5 ms at ζ = 1 "
            "(cost ratio 0.80).") in text
    assert ("- y: no longer step keeps every target the defaults meet: the default step is "
            "the cheapest.") in text
    assert "| y | 5 ms | 1 | diverged | diverged | diverged on the timing drive |" in text


def test_the_default_step_at_another_damping_ratio_is_no_cheaper_step():
    """A row at the default step that keeps every target (a ζ shown for comparison) does not
    make the verdict line name a cheaper step."""
    rows = [{"robot": "x", "timestep": 0.002, "dampratio": 1.0, "rtf": 100.0, "ratio": 1.0,
             "verdict": "the default"},
            {"robot": "x", "timestep": 0.002, "dampratio": 0.8, "rtf": 101.0, "ratio": 0.99,
             "verdict": "seed 0: keeps every target", "acceptable": True}]
    text = timestep_choice.table(rows, [0], timestep_choice.QUICK, quick=False)
    assert "- x: no longer step keeps every target the defaults meet" in text


@pytest.mark.parametrize("argv, message", [
    (["diffdrive", "--dampratios", "1.5"], "--dampratios 1.5"),
    (["diffdrive", "--seeds", "-1"], "--seeds"),
])
def test_bad_options_are_refused_before_any_work(argv, message, capsys):
    with pytest.raises(SystemExit):
        timestep_choice.main(argv)
    assert message in capsys.readouterr().err


def test_a_robot_the_family_does_not_drive_is_refused_by_name(capsys):
    with pytest.raises(SystemExit):
        timestep_choice.main(["--quick", "whipple"])
    assert "'whipple' is not driven by the random-steps family" in capsys.readouterr().err


def test_an_unknown_robot_is_refused_with_the_valid_names():
    with pytest.raises(ValueError, match="nosuchbot"):
        timestep_choice.main(["--quick", "nosuchbot"])


def test_keep_stiffness_studies_those_candidates_and_stops_the_defaults_with_them(
        monkeypatch):
    """``stiffness_kept``: the candidates are ``stiffness_candidates``; once every candidate
    has lost a target, the defaults are not validated at the later seeds either."""
    spec = get_spec("omni3")
    monkeypatch.setattr(timestep_choice, "real_time_factors",
                        lambda s, settings, how, **kw: [50.0] * len(settings))
    seeds_run = []
    monkeypatch.setattr(timestep_choice, "figures",
                        lambda s, p, seed, jobs, cache: seeds_run.append(seed) or {})
    lost = timestep_choice.Fidelity(("random steps / run",), 1, 9)
    monkeypatch.setattr(timestep_choice, "fidelity", lambda *a: lost)
    rows = timestep_choice.study(spec, [0, 1, 2], (), timestep_choice.QUICK, 1,
                                 stiffness_kept=True)
    expected = timestep_choice.stiffness_candidates(spec)
    assert [(r["timestep"], r["dampratio"]) for r in rows[1:]] == [
        (c.timestep, c.dampratio) for c in expected]
    assert all(r["stiffness_kept"] and not r["acceptable"] for r in rows[1:])
    assert seeds_run == [0]
    text = timestep_choice.table(rows, [0], timestep_choice.QUICK, quick=False,
                                 stiffness_kept=True)
    assert "stiffness kept" in text and "| omni3 | 2.5 ms | 0.4 |" in text


def test_keep_stiffness_with_damping_ratios_is_refused(capsys):
    with pytest.raises(SystemExit):
        timestep_choice.main(["omni3", "--keep-stiffness", "--dampratios", "0.5"])
    assert "leave --dampratios out" in capsys.readouterr().err


def test_a_robots_rows_are_replaced_and_the_others_kept():
    """``--write`` with robots named: their rows and verdict lines come from the new run,
    every other robot's stay as the table had them, in registry order, the new header."""
    old = "\n".join([
        "old header", "", "| robot | step |", "|---|---|",
        "| disc | 2.5 ms | old |", "| omni3 | 1.25 ms | old |",
        "| omni3_reduced | 1.25 ms | old |", "| omni3_reduced | 2 ms | old |", "",
        "- disc: old.", "- omni3: old.", "- omni3_reduced: old."])
    new = "\n".join([
        "new header", "", "| robot | step |", "|---|---|",
        "| omni3_reduced | 1.25 ms | new |", "", "- omni3_reduced: new."])
    got = timestep_choice.merged(old, new, ["omni3_reduced"]).splitlines()
    assert got == ["new header", "", "| robot | step |", "|---|---|",
                   "| disc | 2.5 ms | old |", "| omni3 | 1.25 ms | old |",
                   "| omni3_reduced | 1.25 ms | new |", "",
                   "- disc: old.", "- omni3: old.", "- omni3_reduced: new."]


def test_writing_one_robot_into_a_table_of_other_options_is_refused_before_work(
        monkeypatch, capsys):
    """The committed table was made at seeds 0-3: a one-robot ``--write`` at seeds 0, 1
    would relabel every other robot's rows, so it stops before any study runs."""
    monkeypatch.setattr(timestep_choice, "study", lambda *a, **k: pytest.fail("ran"))
    with pytest.raises(SystemExit):
        timestep_choice.main(["omni3", "--seeds", "0", "1", "--write"])
    assert "made with other options" in capsys.readouterr().err
