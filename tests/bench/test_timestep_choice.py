"""Which longer steps keep every target: candidates, the early stop, the table."""

from __future__ import annotations

import math
from fractions import Fraction

import pytest

from wmr_mujoco.bench import timestep_choice
from wmr_mujoco.models.loading import load
from wmr_mujoco.robots import get_spec
from wmr_mujoco.validation.targets import Row


def test_the_steps_are_those_that_divide_every_control_period():
    """1, 1.25, 2, 2.5 and 5 ms divide 20, 50 and 100 ms; 1.5 ms (20/1.5) and 4 ms (50/4)
    do not. Checked by exact rational arithmetic, independently of the module's rule."""
    in_ms = [Fraction(s).limit_denominator(100000) * 1000 for s in timestep_choice.STEPS]
    assert in_ms == [1, Fraction(5, 4), 2, Fraction(5, 2), 5]
    for period_ms in (20, 50, 100):
        assert all((period_ms / s).denominator == 1 for s in in_ms)


@pytest.mark.parametrize("robot", ["omni3", "diffdrive"])
def test_a_longer_step_keeps_the_contact_time_constant_in_steps(robot):
    """MuJoCo as the oracle: the compiled model's floor pairs at the longest step (5 ms)
    have the same ``t_c/Δt`` as at the default step (omni3 sets ``contact_timeconst``
    itself, diffdrive's pairs take it from the step), and the model runs at the new step."""
    spec = get_spec(robot)
    default = load(spec, spec.params_type())
    dt = timestep_choice.STEPS[-1]
    assert dt > default.opt.timestep
    longer = load(spec, timestep_choice.at_step(spec, dt).params)
    assert longer.opt.timestep == dt
    assert default.npair > 0 and longer.npair == default.npair
    steps = default.pair_solref[:, 0] / default.opt.timestep
    assert longer.pair_solref[:, 0] / dt == pytest.approx(steps, rel=1e-12)
    # ζ kept unless asked for
    assert longer.pair_solref[:, 1] == pytest.approx(default.pair_solref[:, 1])
    half = load(spec, timestep_choice.at_step(spec, dt, 0.5).params)
    assert half.pair_solref[:, 1] == pytest.approx(0.5)


def test_candidates_are_the_default_step_at_other_damping_ratios_then_longer_steps():
    spec = get_spec("omni3")  # default 1.25 ms
    own = spec.params_type().sim.floor_dampratio
    assert own not in (0.5, 1.0)
    cands = timestep_choice.candidates(spec, (0.5, 1.0, 0.5, own))
    assert [(c.timestep, c.dampratio) for c in cands] == [(0.00125, 0.5), (0.00125, 1.0)] + [
        (dt, z) for dt in (0.002, 0.0025, 0.005) for z in (own, 0.5, 1.0)]
    assert [(c.timestep, c.dampratio) for c in timestep_choice.candidates(spec)] == [
        (dt, own) for dt in (0.002, 0.0025, 0.005)]


def test_a_robot_without_parameters_is_refused_by_name():
    spec = get_spec("omni3")
    bare = type(spec).__new__(type(spec))
    object.__setattr__(bare, "name", "nameless")
    object.__setattr__(bare, "params_type", None)
    with pytest.raises(ValueError, match="'nameless' has no parameters"):
        timestep_choice.at_step(bare, 0.002)


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
