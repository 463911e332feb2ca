"""The ramped rotation's heading target is open: its family's worst draws drift at the rate
of the requirement.

At 1.19 times the yaw rate, a start angle 12.5 mrad into the 393 mrad roller pitch (at
the zero angle a roller's middle is under each wheel) drifts in heading all run long, at
a steady rate of the one that reaches the 1° requirement over the run; 7.5 mrad earlier,
the same yaw rate drifts at a fraction of it
(``python -m wmr_mujoco.bench.mecanum_drift`` tables both, docs/mecanum.md § 4). A family
whose worst depends on whether a draw lands in that narrow band of start angles passes or
fails by the seed, so the target is open (``ROTATE_RAMP_OPEN``), its spread shown.
"""

import numpy as np

from wmr_mujoco.robots import get_spec, mecanum4
from wmr_mujoco.robots.mecanum4 import TURN_DURATION
from wmr_mujoco.validation.members import run_batched
from wmr_mujoco.validation.variations import INPUT_SCALE, WHEEL_PHASE

HEADING = "worst heading error"
#: The requirement, deg (robots' kinematic targets: heading within 1° over the run).
LIMIT = 1.0
#: The heading error's rate that, held over the run, reaches the requirement, deg/s.
LIMIT_RATE = LIMIT / TURN_DURATION


def _heading_runs(phases):
    spec = get_spec("mecanum4")
    s = spec.scenario("rotate (ramp)")
    members = [s.member({INPUT_SCALE: 1.19, WHEEL_PHASE: p}) for p in phases]
    return run_batched(spec, members, None, None)


def _error_deg(result):
    """Heading error over the run, deg (sim − model, wrapped to ±180°)."""
    a = result.trace.arrays()
    e = np.degrees(a["sim"][:, 2] - a["analytic"][:, 2])
    return a["time"], (e + 180.0) % 360.0 - 180.0


def test_the_ramped_rotation_opens_only_its_heading_target():
    s = get_spec("mecanum4").scenario("rotate (ramp)")
    assert set(s.open_targets) == {HEADING} == set(mecanum4.ROTATE_RAMP_OPEN)


def _drift_rate(result):
    """The heading error's steady rate, deg/s: its least-squares slope over the run's
    second half (the ramp's transient long settled); the error's scatter about that
    line, deg; and the error over time."""
    t, e = _error_deg(result)
    late = t >= 0.5 * t[-1]
    fit = np.polyfit(t[late], e[late], 1)
    return float(fit[0]), float(np.std(e[late] - np.polyval(fit, t[late]))), t, e


def test_a_start_just_past_a_pitch_multiple_drifts_at_the_requirements_rate():
    near, before = _heading_runs([0.0125, 0.005])
    rate, scatter, t, e = _drift_rate(near)
    # The band's draw loses heading steadily at the rate of the requirement: within a
    # factor 2 either way of LIMIT_RATE (half of it would end at half the requirement,
    # twice of it at twice, whatever the seed), the order that makes the family's worst
    # pass or fail by whether a seed draws into the band.
    assert 0.5 * LIMIT_RATE < abs(rate) < 2.0 * LIMIT_RATE
    # Its neighbour outside the band drifts at under half that rate.
    assert abs(_drift_rate(before)[0]) < 0.5 * LIMIT_RATE
    # A drift, not a transient: over the second half the error keeps to its line (a
    # scatter under a tenth of what the line climbs over that half), and it ends at over
    # twice its largest value in the run's first quarter (a transient would have settled).
    assert scatter < 0.1 * abs(rate) * 0.5 * t[-1]
    assert np.abs(e[-1]) > 2.0 * np.abs(e[t <= 0.25 * t[-1]]).max()
