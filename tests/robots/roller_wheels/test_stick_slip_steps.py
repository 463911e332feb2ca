"""The Moreau step on Python floats gives the floats of its equations written on numpy arrays."""

import numpy as np
import pytest

from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.roller_stick_slip import (
    BoxLcp,
    RollerPlatform,
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


def numpy_step(p, lcp, q_dot, commanded, accel, step, guess):
    """The Moreau step (roller_stick_slip's module docstring) on numpy arrays: the
    reference whose floats the Python-float step must give (the same operations, each
    rounded once, in the same order; the matrix products the same BLAS calls)."""
    base, per_ax, per_ay = p._transfer
    loads = np.maximum(base + accel[0] * per_ax + accel[1] * per_ay, 0.0)
    minv, jac = p.inverse_mass, p.jacobian
    u, v, r = q_dot[:3]
    forces = np.concatenate([[p.mass * r * v, -p.mass * r * u, 0.0],
                             p.servo_torques(q_dot[3:], commanded)])
    q_free = q_dot + step * minv * forces
    slip_free = jac @ q_free
    imp, state = lcp.solve(slip_free, p.friction * loads * step, guess)
    q_new = q_free + minv * (jac.T @ imp)
    nu_dot = (q_new[:3] - q_dot[:3]) / step
    accel_new = np.array([nu_dot[0] - q_new[2] * q_new[1], nu_dot[1] + q_new[2] * q_new[0]])
    return q_new, imp, slip_free + lcp.w @ imp, state, loads, accel_new


def reference(p, cmd, nstep, step=1e-4):
    """:func:`numpy_step` in a plain loop: the rows step_response keeps."""
    lcp = BoxLcp(p.delassus)
    q, accel, state = np.zeros(7), np.zeros(2), None
    rows = {"q": [], "p": [], "loads": [], "state": [], "dissipated": []}
    dissipated = 0.0
    for _ in range(nstep):
        q, imp, slip, state, loads, accel = numpy_step(p, lcp, q, cmd, accel, step, state)
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
def test_march_is_the_numpy_step_bit_for_bit(twist, kw, switches):
    p = platform(**kw)
    cmd = H @ np.array(twist)
    nstep = 1500  # 0.15 s: the rise of each command (slip, hand-over to stick), sticking
    got = march(p, BoxLcp(p.delassus), cmd, nstep, nstep, 1e-4, -1.0)
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
        march(p, BoxLcp(p.delassus), np.array([np.nan, 0.0, 0.0, 0.0]), 10, 10, 1e-4, 1e-9)


def test_advance_is_one_step_of_march():
    # advance (arrays) and march (lists) are the one step: from rest, a turn's first
    # steps give the same floats, each step's acceleration fed to the next.
    p = platform(com_height=0.05)
    cmd = H @ np.array([0.2, -0.1, 1.0])
    lcp = BoxLcp(p.delassus)
    rows = march(p, lcp, cmd, 50, 50, 1e-4, -1.0)
    q, accel, state = np.zeros(7), np.zeros(2), None
    for k in range(50):
        q, imp, _, state, loads, accel = advance(p, lcp, q, cmd, accel, 1e-4, state)
        np.testing.assert_array_equal(q, rows["q"][k])
        np.testing.assert_array_equal(imp, rows["p"][k])
        np.testing.assert_array_equal(loads, rows["loads"][k])
        assert state == rows["state"][k]
