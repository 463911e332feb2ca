"""The ramped rotation's heading target is open: its family's worst draws cross 1°.

At 1.19 times the yaw rate, a start angle 12.5 mrad into the 393 mrad roller pitch (at
the zero angle a roller's middle is under each wheel) drifts in heading all run long
and ends beyond the 1° requirement
(``wmr validate mecanum4 --scenario "rotate (ramp)" --seed 1179`` judged such a draw,
1.003°); 7.5 mrad earlier, the same yaw rate keeps within half of it. A family whose
worst depends on whether a draw lands in that narrow band of start angles passes or
fails by the seed, so the target is open (``ROTATE_RAMP_OPEN``), its spread shown.
"""

import numpy as np

from wmr_mujoco.robots import get_spec, mecanum4
from wmr_mujoco.validation.members import run_batched
from wmr_mujoco.validation.variations import INPUT_SCALE, WHEEL_PHASE

HEADING = "worst heading error"
#: The requirement, deg (robots' kinematic targets: heading within 1° over the run).
LIMIT = 1.0


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


def test_a_start_just_past_a_pitch_multiple_drifts_past_the_requirement():
    near, before = _heading_runs([0.0125, 0.005])
    worst = {r.scenario.draw[WHEEL_PHASE]: next(x.value for x in r.rows if x.metric == HEADING)
             for r in (near, before)}
    assert worst[0.0125] > LIMIT  # the family's worst crosses the requirement ...
    assert worst[0.005] < 0.5 * LIMIT  # ... in a band a few mrad of start angle wide
    # A drift, not a transient: the error at the end of the run is the largest, over
    # twice the error at its first quarter (a transient would have settled by then).
    t, e = _error_deg(near)
    quarter = np.abs(e[t <= 0.25 * t[-1]]).max()
    assert np.abs(e[-1]) >= 0.99 * np.abs(e).max()
    assert np.abs(e[-1]) > 2.0 * quarter
