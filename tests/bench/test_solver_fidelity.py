"""The validation of a solver setting against the defaults, row by row."""

from __future__ import annotations

import dataclasses
import json
import math

import pytest

from wmr_mujoco.bench import solver_fidelity
from wmr_mujoco.bench.solver_cost import SETTINGS
from wmr_mujoco.robots import get_spec
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.validation.targets import Row


def _setting(label):
    return next(s for s in SETTINGS if s.label == label)


def _row(value, passed, target=1.0, metric="m", unit=""):
    return Row("r", "s", metric, value, unit, target, passed)


def _rows(*rows):
    return {(r.scenario, r.metric, r.unit): r for r in rows}


def test_compare_finds_a_lost_target_and_the_largest_rise_as_a_share_of_target():
    default = _rows(_row(0.5, True, 1.0, "a"), _row(2.0, True, 4.0, "b"),
                    _row(3.0, False, 1.0, "c"), _row(0.1, None, 0.01, "open"))
    setting = _rows(_row(1.5, False, 1.0, "a"), _row(-2.4, True, 4.0, "b"),
                    _row(3.0, False, 1.0, "c"), _row(0.9, None, 0.01, "open"))
    v = solver_fidelity.compare(default, setting)
    assert v.lost == ("s / a",)  # c failed already: not lost
    # (1.5 − 0.5) / 1 beats (2.4 − 2) / 4; the open row's 80-fold rise is not judged
    assert v.worst_rise == pytest.approx(1.0)
    assert v.worst_row == "s / a"
    assert not v.acceptable


def test_compare_counts_a_missing_row_and_a_nan_figure_as_failures():
    default = _rows(_row(0.5, True, metric="a"), _row(0.1, True, metric="b"))
    setting = _rows(_row(math.nan, False, metric="a"))
    v = solver_fidelity.compare(default, setting)
    assert v.missing == ("s / b",)
    assert v.lost == ("s / a",)
    assert math.isnan(v.worst_rise) and v.worst_row == "s / a"


def test_an_unchanged_setting_is_acceptable_with_no_rise():
    rows = _rows(_row(0.5, True, 1.0, "a", "%"), _row(0.1, None, None, "a", "m"))
    v = solver_fidelity.compare(rows, dict(rows))
    assert v.acceptable and v.worst_rise == 0.0


def test_cached_figures_are_read_back_and_keyed_by_the_model(tmp_path):
    """A setting that changes the model file gets its own cache file; rows written there
    are what ``figures`` returns (no validation runs)."""
    spec = get_spec("omni3")
    default, dense = OmniParams(), OmniParams(jacobian="dense")
    path = solver_fidelity.cache_file(spec, default, 0, tmp_path)
    assert path != solver_fidelity.cache_file(spec, dense, 0, tmp_path)
    assert path != solver_fidelity.cache_file(spec, default, 1, tmp_path)
    rows = [_row(0.25, True, 1.0, "a", "%"), _row(0.01, None, None, "a", "m")]
    path.write_text(json.dumps([dataclasses.asdict(r) for r in rows]))
    # one metric in two units: two rows, neither hiding the other
    assert solver_fidelity.figures(spec, default, 0, cache=tmp_path) == _rows(*rows)


def test_a_setting_rejected_at_one_seed_runs_no_later_seed(monkeypatch):
    """The validation itself is the project's (`wmr validate`'s families); here only the
    bookkeeping: figures faked per (setting, seed), the sparse setting losing its one
    target at seed 0, so seed 1 is never asked for."""
    spec = get_spec("omni3")
    asked = []

    def fake(spec_, params, seed, jobs=1, cache=None):
        asked.append((params.jacobian, seed))
        bad = params.jacobian == "dense"
        return _rows(_row(2.0 if bad else 0.5, not bad))

    monkeypatch.setattr(solver_fidelity, "figures", fake)
    cell = solver_fidelity.judge_settings(spec, [_setting("jacobian dense")], [0, 1],
                                          progress=False)
    assert asked == [("sparse", 0), ("dense", 0)]
    assert cell["jacobian dense"].startswith("seed 0: loses 1: s / m;")


def test_without_running_only_kept_figures_give_a_verdict(tmp_path):
    """``run=False`` reads the cache and runs nothing: a setting whose figures are kept
    gets its verdict, one without is left out."""
    spec = get_spec("omni3")
    for params, value in ((OmniParams(), 0.5), (OmniParams(solver="PGS"), 0.6)):
        path = solver_fidelity.cache_file(spec, params, 0, tmp_path)
        path.write_text(json.dumps([dataclasses.asdict(_row(value, True))]))
    cells = solver_fidelity.judge_settings(spec, [_setting("PGS"), _setting("CG")], [0, 1],
                                           progress=False, cache=tmp_path, run=False)
    assert list(cells) == ["PGS"]
    assert cells["PGS"].startswith("seed 0: passes all; worst rise +10.0% of target")


def test_an_open_target_met_by_the_defaults_is_lost_when_the_setting_misses_it():
    """An open target (not judged: another draw of the family misses it) still counts where
    the defaults' figure meets it: a setting may not worsen it past its target unseen. An
    open target the defaults miss already is not lost again."""
    def open_row(value, metric):
        return Row("r", "s", metric, value, "", 1.0, None, open=True)

    default = _rows(open_row(0.8, "met"), open_row(3.0, "missed"), _row(0.2, None, None, "shown"))
    setting = _rows(open_row(1.2, "met"), open_row(9.0, "missed"), _row(5.0, None, None, "shown"))
    assert solver_fidelity.meets(default[("s", "met", "")])
    assert not solver_fidelity.meets(default[("s", "shown", "")])  # no target: nothing to meet
    v = solver_fidelity.compare(default, setting)
    assert v.lost == ("s / met",)
    assert v.worst_rise == float("-inf")  # no judged row: no rise


def test_a_failed_row_of_the_setting_alone_is_lost():
    """A member that diverged leaves a failed ``run`` row the defaults do not have, while
    its siblings still give every metric: the setting loses it."""
    default = _rows(_row(0.5, True, metric="a"))
    setting = _rows(_row(0.5, True, metric="a"), _row(math.nan, False, None, "run"))
    v = solver_fidelity.compare(default, setting)
    assert v.lost == ("s / run",) and not v.acceptable
