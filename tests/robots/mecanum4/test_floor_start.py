"""The random steps' start-up target is open for mecanum4: a roller hand-over lifts a wheel.

``wmr validate mecanum4 --scenario "random steps" --seed 102`` judged 1.25 % of wheel
samples off the floor in the first 0.1 s after the step from rest (requirement 1 %,
issue 24 § 3); of 160 draws (seeds 100-107) four missed it, each starting with the wheels
within 0.015 rad of half a roller pitch. The draw below (seed 105, member 4) is run at
that start angle and a quarter pitch to either side with the same commands.
"""

import math

import pytest

from wmr_mujoco.robots import get_spec, mecanum4
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.validation import floor_family as ff

_DRAW = {ff.WHEEL_PHASE: 5.302811186938855, ff.INPUTS: 0.18715966019721797}
PITCH = 2.0 * math.pi / MecanumParams().rollers_per_wheel


def _after_step(shift: float) -> float:
    spec = get_spec("mecanum4")
    s = spec.scenario(ff.NAME)
    member = s.member({**_DRAW, ff.WHEEL_PHASE: _DRAW[ff.WHEEL_PHASE] + shift})
    return next(m.value for m in ff.measure(spec, member).metrics if m.name == ff.AFTER_STEP)


def test_only_the_start_up_share_is_open():
    s = get_spec("mecanum4").scenario(ff.NAME)
    assert set(s.open_targets) == {ff.AFTER_STEP} == set(mecanum4.FLOOR_OPEN[ff.NAME])


def test_the_draw_starts_at_a_roller_hand_over():
    # Half a pitch from the zero angle (where a roller's middle is under each wheel; at
    # half a pitch two rollers are equally low), to 1 % of the pitch.
    assert _DRAW[ff.WHEEL_PHASE] % PITCH == pytest.approx(0.5 * PITCH, abs=0.01 * PITCH)


def test_a_hand_over_start_lifts_a_wheel_that_a_quarter_pitch_away_stays_down():
    step = ff.STEP_TARGET.value  # 1 % of the wheel samples in the first 0.1 s
    assert _after_step(0.0) > step
    # A quarter pitch either way puts the contact on a roller's flank: no sample lifts
    # (0 %, to one sample of the 320 in the window: 4 wheels x 80 steps).
    for shift in (0.25 * PITCH, -0.25 * PITCH):
        assert _after_step(shift) <= 100.0 / 320.0
