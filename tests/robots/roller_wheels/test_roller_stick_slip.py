"""The stick–slip step model, each term against an independent closed form or model."""

import math

import numpy as np
import pytest
from scipy.optimize import minimize

from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.omni_dynamics import OmniDynamics
from wmr_mujoco.robots.roller_wheels.roller_stick_slip import (
    BoxLcp,
    RollerPlatform,
    advance,
    box_lcp,
    step_response,
)
from wmr_mujoco.robots.roller_wheels.roller_traction import acceleration_time

A, W, R, M, IZ, IW, MU, G = 0.15, 0.12, 0.05, 4.0, 0.08, 0.004, 0.8, 9.81
LAY = ok.mecanum_layout(R, A, W)
H = ok.wheel_jacobian(LAY)


def platform(**kw):
    args = {"layout": LAY, "mass": M, "yaw_inertia": IZ, "wheel_inertia": IW,
            "servo_gain": 2.0, "torque_limit": 3.0, "friction": MU}
    args.update(kw)
    return RollerPlatform(**args)


def test_all_stick_is_the_reduced_lagrange_model():
    # With friction out of reach every contact sticks (ω = H ν) and one Moreau step's
    # acceleration is the reduced model's (M + I_w HᵀH) ν̇ + c = Hᵀ τ (omni_dynamics,
    # derived by eliminating the traction forces): the rows J are constant in the body
    # frame, so J q̇ = 0 before and after the step makes the step exact up to rounding.
    p = platform(friction=1e6)
    nu = np.array([0.2, -0.1, 0.7])
    q = np.concatenate([nu, H @ nu])
    cmd = H @ np.array([0.3, 0.1, 0.2])
    h = 1e-7
    q_new, *_, state, _, _ = advance(p, BoxLcp(p.delassus), q, cmd, np.zeros(2), h)
    assert state == (0, 0, 0, 0)
    tau = p.servo_torques(q[3:], cmd)
    want = OmniDynamics(M, IZ, IW, LAY).body_acceleration(nu, tau)
    np.testing.assert_allclose((q_new[:3] - nu) / h, want, rtol=1e-6, atol=1e-6)


def test_forward_slip_acceleration_is_the_closed_form():
    # Along x every contact slips at μ N along its 45° roller: u̇ = μ g cos 45° = μ g/√2,
    # and each wheel turns at I_w ω̇ = τ − R cos γ μ N; exact in the slip phase (constant
    # forces), so to rounding. Load transfer moves N between axles but not their sum.
    p = platform(com_height=0.05)
    r = step_response(p, H @ np.array([0.3, 0.0, 0.0]), 0.03, step=1e-4)
    slip = np.flatnonzero(~np.any(r.stuck, axis=1))
    k = slip[(r.time[slip] > 0.005) & (r.time[slip] < 0.025)]
    u_dot = np.diff(r.twist[:, 0])[k - 1] / 1e-4
    np.testing.assert_allclose(u_dot, MU * G / math.sqrt(2), rtol=1e-9)
    np.testing.assert_allclose(r.twist[k, 1:], 0.0, atol=1e-12)


def test_wheel_spin_up_while_slipping_is_the_closed_form():
    p = platform()
    r = step_response(p, H @ np.array([0.3, 0.0, 0.0]), 0.003, step=1e-4)
    # Saturated servo (error 6 rad/s ≫ τ_max/k_v), load m g/4, no transfer.
    want = (3.0 - R * math.cos(math.pi / 4) * MU * M * G / 4) / IW
    np.testing.assert_allclose(np.diff(r.wheel_rates[:, 0])[1:20] / 1e-4, want, rtol=1e-9)


#: A stiff, strong servo on light wheels: k_v h / I_w = 0.8 < 1 keeps the explicit servo
#: monotone at the internal step h.
FAST = {"servo_gain": 40.0, "torque_limit": 200.0, "wheel_inertia": 1e-3}
HF = 2e-5
#: Torque a slipping contact needs from its wheel, R cos γ μ m g/4, N·m.
TAU_C = R * math.cos(math.pi / 4) * MU * M * G / 4


def allowances(cmd):
    """Spin-up time t_s = I_w ω / (τ_max − τ_c) and the servo's rate deficit τ_c / k_v."""
    omega = float(np.max(np.abs(cmd)))
    return (FAST["wheel_inertia"] * omega / (FAST["torque_limit"] - TAU_C),
            TAU_C / FAST["servo_gain"] / omega)


@pytest.mark.parametrize("twist", [(0.3, 0.0, 0.0), (0.0, -0.3, 0.0),
                                   (0.3 / math.sqrt(2), 0.3 / math.sqrt(2), 0.0),
                                   (0.0, 0.0, 1.0)])
def test_rise_time_is_the_traction_limited_one(twist):
    # A fast servo leaves the traction limit alone: the contacts stick at T = 1/s_max of
    # the linear programme in roller_wheels.roller_traction (independent: an LP over the
    # force polytope). Allowances: the wheels' spin-up t_s (the rims may lag the chassis
    # then), the rims' steady deficit under the slip torque (they run slow by
    # δω/ω = τ_c / (k_v ω), so the chassis meets them δω/ω·T early), one internal step.
    cmd = H @ np.array(twist)
    r = step_response(platform(**FAST), cmd, 0.2, step=HF)
    t_lp = acceleration_time(LAY, M, IZ, np.full(4, M * G / 4), MU, np.array(twist))
    t_s, deficit = allowances(cmd)
    assert abs(r.rise_time - t_lp) <= t_s + deficit * t_lp + HF


def test_slip_dissipation_is_half_m_v_squared():
    # A body dragged from rest to V by a surface already at V loses ½ m V² to friction
    # (∫ m a (V − u) dt with a constant; the conveyor-belt result). Fast servo as above;
    # allowances: the spin-up t_s (less slip then) and one step h at the friction power
    # μ m g cos γ · V, and the rims' deficit δω/ω (½ m V² scales with V²: twice it).
    cmd = H @ np.array([0.3, 0.0, 0.0])
    r = step_response(platform(**FAST), cmd, 0.2, step=HF)
    t_s, deficit = allowances(cmd)
    want = 0.5 * M * 0.3**2
    power = MU * M * G / math.sqrt(2) * 0.3
    assert r.dissipated[-1] == pytest.approx(want, abs=power * (t_s + HF)
                                             + 2 * deficit * want)


def test_load_transfer_balances_weight_and_moments():
    # Quasi-static: Σ N = m g; pitch Σ N x = −m h a_x; roll Σ N y = −m h a_y (the floor
    # forces at ground level, the inertial force at the centre of mass, height h).
    h_c = 0.05
    p = platform(com_height=h_c)
    n = p.loads(np.array([3.0, -2.0]))
    pos = LAY.positions
    assert np.sum(n) == pytest.approx(M * G, rel=1e-12)
    assert n @ pos[:, 0] == pytest.approx(-M * h_c * 3.0, rel=1e-12)
    assert n @ pos[:, 1] == pytest.approx(-M * h_c * -2.0, rel=1e-12)


def test_box_lcp_is_the_minimum_of_the_friction_qp():
    # The box LCP is the optimality condition of min ½ PᵀWP + Pᵀs over |P_i| ≤ b_i:
    # a bounded quasi-Newton minimiser (scipy) solves the same problem independently.
    rng = np.random.default_rng(3)
    for _ in range(5):
        a = rng.normal(size=(4, 4))
        w = a @ a.T + 0.5 * np.eye(4)
        s0 = rng.normal(size=4)
        b = rng.uniform(0.05, 0.5, size=4)
        p, _ = box_lcp(w, s0, b)
        ref = minimize(lambda x, w=w, s0=s0: 0.5 * x @ w @ x + x @ s0, np.zeros(4),
                       jac=lambda x, w=w, s0=s0: w @ x + s0, method="L-BFGS-B",
                       bounds=list(zip(-b, b, strict=True)), options={"gtol": 1e-12,
                                                                      "ftol": 1e-15})
        np.testing.assert_allclose(p, ref.x, atol=1e-6)


@pytest.mark.parametrize(("field", "value"), [("mass", 0.0), ("friction", -1.0),
                                              ("com_height", -0.1),
                                              ("torque_limit", math.inf)])
def test_bad_parameters_are_refused(field, value):
    with pytest.raises(ValueError, match=field):
        platform(**{field: value})


@pytest.mark.parametrize(("kw", "match"), [({"duration": 0.0}, "duration"),
                                           ({"step": 0.01}, "step")])
def test_bad_run_settings_are_refused(kw, match):
    args = {"duration": 0.1} | kw
    with pytest.raises(ValueError, match=match):
        step_response(platform(), np.zeros(4), **args)
