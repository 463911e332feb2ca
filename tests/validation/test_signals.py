import math

import pytest

from wmr_mujoco.validation.signals import Piecewise, Sine, const, pulses


def test_piecewise_interpolates_and_holds():
    s = Piecewise(((1.0, 0.0), (3.0, 2.0)))
    assert [s(0.0), s(1.0), s(2.0), s(3.0), s(9.0)] == [0.0, 0.0, 1.0, 2.0, 2.0]


def test_const_ramp_and_pulses():
    assert const(2.0, 0.5)(0.25) == pytest.approx(1.0)
    assert const(2.0)(0.0) == 2.0
    p = pulses((1.0, 2.0, 3.0))
    assert [p(0.5), p(1.5), p(2.5)] == [0.0, 3.0, 0.0]


def test_sine():
    assert Sine(2.0, 4.0)(1.0) == pytest.approx(2.0)
    assert Sine(1.0, 2.0, offset=0.5, phase=math.pi / 2)(0.0) == pytest.approx(1.5)


@pytest.mark.parametrize("call, match", [
    (lambda: Piecewise(()), "need at least one"),
    (lambda: Piecewise(((2.0, 0.0), (1.0, 1.0))), "in time order"),
    (lambda: Sine(1.0, 0.0), "period = 0.0"),
])
def test_bad_signals(call, match):
    with pytest.raises(ValueError, match=match):
        call()


@pytest.mark.parametrize("value, ramp, match", [
    (1.0, -0.5, r"ramp = -0.5 s; must be a finite number in \[0, inf\)"),
    (1.0, math.nan, r"ramp = nan s"),
    (1.0, math.inf, r"ramp = inf s"),
    (math.nan, 0.5, r"value = nan; must be a finite number"),
])
def test_const_refuses_a_bad_value_or_ramp(value, ramp, match):
    with pytest.raises(ValueError, match=match):
        const(value, ramp)
