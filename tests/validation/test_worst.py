"""A family is judged by its worst member; its spread (median, percentiles) is reported."""

import math

import numpy as np
import pytest

from wmr_mujoco.validation.metrics import Metric
from wmr_mujoco.validation.targets import Row, Target
from wmr_mujoco.validation.worst import badness, spreads, worst_member, worst_rows

REQ = Target.requirement(1.0, "asked")
OPEN = Target.open(1.0, "asked", "no model yet")


def rows(err: float, other: float = 0.1, open_: float = 0.5) -> list[Row]:
    return [Row.of("r", "s", Metric("error", err, "%", REQ)),
            Row.of("r", "s", Metric("other", other, "%", REQ)),
            Row.of("r", "s", Metric("open one", open_, "%", OPEN))]


def test_one_failing_member_fails_the_family_and_is_the_row_shown():
    members = [rows(0.2), rows(1.5, other=0.05), rows(-0.9)]
    draws = [{"x": 1.0}, {"x": 2.0}, {"x": 3.0}]
    out = {r.metric: r for r in worst_rows(members, draws)}
    assert out["error"].value == 1.5 and out["error"].passed is False
    assert "x=2" in out["error"].note and "worst of 3" in out["error"].note
    # Each metric's worst is its own: "other" is worst in the first member.
    assert out["other"].value == 0.1 and out["other"].passed is True
    assert worst_member(members) == 1


def test_a_signed_worst_and_a_non_finite_member():
    members = [rows(0.2), rows(-0.95), rows(math.nan)]
    out = {r.metric: r for r in worst_rows(members, [{}, {}, {}])}
    assert math.isnan(out["error"].value) and out["error"].passed is False
    members = [rows(0.2), rows(-0.95)]
    out = {r.metric: r for r in worst_rows(members, [{}, {}])}
    assert out["error"].value == -0.95 and out["error"].passed is True


def test_an_open_target_shows_its_worst_and_is_not_judged():
    out = {r.metric: r for r in worst_rows([rows(0.1, open_=0.3), rows(0.1, open_=2.0)],
                                           [{}, {}])}
    assert out["open one"].open and out["open one"].passed is None
    assert out["open one"].value == 2.0 and out["open one"].verdict == "open"


def test_spread_figures():
    values = [0.1, 0.2, 0.3, 0.4, -0.9]
    s = {x.metric: x for x in spreads([rows(v) for v in values])}["error"]
    assert s.n == 5 and s.median == pytest.approx(np.median(values))
    assert s.percentile(90) == pytest.approx(np.percentile(values, 90))
    assert (s.low, s.high, s.worst, s.passed) == (-0.9, 0.4, -0.9, True)


def test_badness_is_the_ratio_to_the_target():
    assert badness(rows(0.5)[0]) == 0.5
    assert badness(Row.of("r", "s", Metric("x", -3.0, "m"))) == 3.0
    assert badness(rows(math.inf)[0]) == math.inf
