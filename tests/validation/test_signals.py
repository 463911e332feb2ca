import math

import numpy as np
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


def test_on_gives_the_floats_of_a_call_at_every_time():
    """``on`` is the scalar call elementwise: same arithmetic, so the same floats.

    Times before, on and between knots, a step (two knots at one time) and a hold after
    the last knot; the sine's libm and NumPy sin may differ in the last bit on some
    CPUs, hence its 1e-15 relative tolerance.
    """
    from wmr_mujoco.validation.signals import Held

    times = np.arange(4000) * 0.00125
    signals = [Piecewise(((0.5, -1.0), (1.0, 2.0), (1.0, 3.0), (2.5, 0.25), (4.0, 0.25))),
               const(0.3, 0.5), pulses((0.2, 0.7, 1.5), (1.0, 3.0, -2.0)),
               Held(Piecewise(((0.0, 0.0), (2.0, 1.0))), 1.3)]
    for s in signals:
        np.testing.assert_array_equal(s.on(times), [s(t) for t in times])
    for s in (Sine(0.4, 1.7, offset=0.1, phase=0.3), Held(Sine(1.0, 2.0), 3.0)):
        np.testing.assert_allclose(s.on(times), [s(t) for t in times], rtol=1e-15,
                                   atol=1e-15)
