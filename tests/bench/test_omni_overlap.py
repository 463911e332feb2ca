"""omni3's overlap measurement: two rollers of a turning wheel slide against each other."""

import math

import pytest

from wmr_mujoco.bench import omni_overlap as ov


def test_two_touching_rollers_slide_against_each_other():
    """A short coast while turning: the two rollers of a wheel that touch together sit at
    levers L ± e, which ask rim speeds 2 e r apart; the wheel turns at one rate, so at most
    one of them rolls and the other slides against it. Their friction forces along the
    drive direction therefore point in opposite directions on most loaded overlap steps
    (more than half; a step where one contact rolls and carries the wheel's own
    acceleration can go either way), and every share is a fraction."""
    rows = ov.overlap_windows((0.3, 0.0, 1.0), drive_time=1.0, duration=1.0)
    assert [r["wheel"] for r in rows] == [1, 2, 3]
    loaded = [r for r in rows if r["loaded pair steps"] > 0]
    assert loaded, "no wheel had two loaded rollers in a turning coast"
    for r in loaded:
        assert r["friction forces opposed"] > 0.5
        assert 0.0 <= r["lighter contact's share"] <= 0.5
        assert 0.0 <= r["contacts at the Coulomb limit"] <= 1.0
    for r in rows:
        assert math.isfinite(r["static window (steps)"]) and r["static window (steps)"] > 0
    assert "linear sharing: 0.25" in ov.table(rows)


@pytest.mark.parametrize("kwargs, match", [({"twist": (0.3, math.inf, 0.0)}, "twist"),
                                           ({"duration": -1.0}, "duration"),
                                           ({"drive_time": math.nan}, "drive_time")])
def test_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        ov.overlap_windows(**kwargs)
