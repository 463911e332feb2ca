"""The ramped turn's drifting draws lose yaw rate in contact slip, not in kinematics.

Two members of ``rotate (ramp)`` at 1.19 times the yaw rate (seed 1179's worst): 12.5 mrad
past a roller's middle (drifts past the 1° requirement) and 5 mrad (keeps within half).
"""

import math

import numpy as np
import pytest

from wmr_mujoco.bench import mecanum_drift as md
from wmr_mujoco.robots.mecanum4 import TURN_DURATION
from wmr_mujoco.robots.roller_wheels import YAW_RATE

#: The yaw-rate error that, held over the run, reaches the 1° heading requirement:
#: (π/180) / (scale · yaw rate · duration), about 0.15 % here.
STEADY_LIMIT = math.radians(1.0) / (md.SCALE * YAW_RATE * TURN_DURATION)
#: The start angles past a roller's middle: the neighbour that keeps, the draw that drifts.
KEEP, DRIFT = md.PHASES


@pytest.fixture(scope="module")
def runs():
    return {p: md.per_second(p) for p in md.PHASES}


def test_bad_input_is_refused_before_any_run():
    with pytest.raises(ValueError, match="phase"):
        md.record(-0.1)
    with pytest.raises(ValueError, match="scale"):
        md.record(0.01, 2.0)


def test_the_offset_term_is_the_mirror_symmetric_least_squares():
    # The two diagonals are mirror images in the turn, so an offset either way changes
    # the twist alike (to round-off of the 4096-sample mean).
    d = math.radians(3.0)
    assert md.offset_effect(d) == pytest.approx(md.offset_effect(-d), rel=1e-9, abs=1e-12)


def test_the_drifting_draw_loses_rate_the_kinematics_do_not_explain(runs):
    drift, keep = runs[DRIFT], runs[KEEP]
    residual = lambda r: float(np.mean(r["measured"] - r["kinematic"]))  # noqa: E731
    # The drifting draw: a steady loss beyond the kinematics of its measured phases and
    # wheel rates, of the size that crosses the requirement over the run (more than half
    # of it); the kinematic part alone stays below a fifth of it.
    assert residual(drift) < -0.5 * STEADY_LIMIT
    assert np.abs(drift["kinematic"]).max() < 0.2 * STEADY_LIMIT
    # Its neighbour follows its kinematics: the mean residual within a quarter of it.
    assert abs(residual(keep)) < 0.25 * STEADY_LIMIT


def test_the_drifting_draw_holds_its_torque_on_one_diagonal(runs):
    # A rate servo droops by torque / gain: the diagonal whose rate falls short carries
    # the drive. In the drifting draw FL and RR fall short of FR and RL every second and
    # the roller-phase offset grows one way; in its neighbour the drive changes diagonal
    # during the run and the offset stays within the start's 2p.
    split = lambda r: r["rates"][:, [0, 3]].mean(1) - r["rates"][:, [1, 2]].mean(1)  # noqa: E731
    drift, keep = runs[DRIFT], runs[KEEP]
    assert (split(drift) < 0.0).all()
    assert np.diff(drift["offset"]).max() < 0.0
    assert (split(keep) < 0.0).any() and (split(keep) > 0.0).any()
    assert np.abs(keep["offset"]).max() <= 2.0 * KEEP
