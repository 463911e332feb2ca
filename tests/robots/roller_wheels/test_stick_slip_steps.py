"""The step response's fast loop gives the floats of ``advance``, step after step."""

import numpy as np
import pytest

from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.roller_stick_slip import (
    BoxLcp,
    RollerPlatform,
    _states,
    advance,
    step_response,
)
from wmr_mujoco.robots.roller_wheels.stick_slip_steps import march

LAY = ok.mecanum_layout(0.05, 0.15, 0.12)
H = ok.wheel_jacobian(LAY)


def platform(**kw):
    args = {"layout": LAY, "mass": 4.0, "yaw_inertia": 0.08, "wheel_inertia": 0.004,
            "servo_gain": 2.0, "torque_limit": 3.0, "friction": 0.8, "com_height": 0.05}
    args.update(kw)
    return RollerPlatform(**args)


def reference(p, cmd, nstep, step=1e-4):
    """``advance`` in a plain loop: the rows step_response keeps."""
    lcp = BoxLcp(p.delassus)
    q, accel, state = np.zeros(7), np.zeros(2), None
    rows = {"q": [], "p": [], "loads": [], "state": [], "dissipated": []}
    dissipated = 0.0
    for _ in range(nstep):
        q, imp, slip, state, loads, accel = advance(p, lcp, q, cmd, accel, step, state)
        dissipated -= float(imp @ slip)
        for key, value in zip(rows, (q, imp, loads, state, dissipated), strict=True):
            rows[key].append(value)
    return rows


# Slip along x (all four contacts at the bound), a diagonal (two wheels idle), a turn
# with load transfer (each slips, then sticks: ``switches``), a servo held at its torque
# limit by a large command (sticking throughout) and friction out of reach: every
# branch of the contact solve and of the servo clip is taken.
@pytest.mark.parametrize("twist, kw, switches", [
    ((0.3, 0.0, 0.0), {}, True), ((0.25, 0.25, 0.0), {}, True),
    ((0.2, -0.1, 1.0), {}, True), ((1.5, 0.0, 0.0), {"torque_limit": 0.05}, False),
    ((0.3, 0.0, 0.0), {"friction": 1e6}, False)])
def test_march_is_advance_bit_for_bit(twist, kw, switches):
    p = platform(**kw)
    cmd = H @ np.array(twist)
    nstep = 1500  # 0.15 s: the rise of each command (slip, hand-over to stick), sticking
    got = march(p, BoxLcp(p.delassus), _states(4), cmd, nstep, nstep, 1e-4, -1.0)
    want = reference(p, cmd, nstep)
    assert len(got["q"]) == nstep
    np.testing.assert_array_equal(np.asarray(got["q"]), np.asarray(want["q"]))
    np.testing.assert_array_equal(np.asarray(got["p"]), np.asarray(want["p"]))
    np.testing.assert_array_equal(np.asarray(got["loads"]), np.asarray(want["loads"]))
    assert got["state"] == want["state"]
    assert got["dissipated"] == want["dissipated"]
    assert (len(set(want["state"])) > 1) == switches


def test_march_stops_at_the_fixed_point():
    # A whole chunk sticking with the twist still to 1e-9: the run ends there, before
    # its duration, and holds its last twist (StepResponse.twist_at).
    p = platform()
    r = step_response(p, H @ np.array([0.3, 0.0, 0.0]), 2.0)
    assert r.time[-1] < 1.0
    assert np.all(r.stuck[-500:])
    np.testing.assert_allclose(r.twist_at(1.5), r.twist[-1], atol=0.0)


def test_march_reports_divergence():
    # A NaN command: the servo clip keeps it (as numpy's), the first step's state is
    # not finite, and the run stops there.
    p = platform()
    with pytest.raises(ValueError, match="diverged at t = 0.0001 s"):
        march(p, BoxLcp(p.delassus), _states(4), np.array([np.nan, 0.0, 0.0, 0.0]), 10, 10,
              1e-4, 1e-9)
