import numpy as np
import pytest

from wmr_mujoco.analytic.wheel_dynamics import GRAVITY, SlipPulse, WheelDynamics


def test_rolling_wheel_solves_the_two_equations():
    w = WheelDynamics(mass=2.0, inertia=0.017, radius=0.15)
    tau = 0.4
    # Unknowns (ẍ, θ̈, F): m ẍ − F = 0, J θ̈ + R F = τ, ẍ − R θ̈ = 0.
    A = np.array([[w.mass, 0, -1], [0, w.inertia, w.radius], [1, -w.radius, 0]])
    xdd, thdd, force = np.linalg.solve(A, [0, tau, 0])
    assert w.rolling_acceleration(tau) == pytest.approx(xdd)
    assert w.traction_force(tau) == pytest.approx(force)
    assert w.accelerations(tau, 1.0, 1.0 / w.radius) == pytest.approx((xdd, thdd))


def test_friction_limit_separates_rolling_from_slip():
    w = WheelDynamics(mass=2.0, inertia=0.017, radius=0.15, friction=0.3)
    limit = w.max_rolling_torque
    assert w.traction_force(limit) == pytest.approx(0.3 * 2.0 * GRAVITY)
    assert not w.slips(0.999 * limit) and w.slips(1.001 * limit)
    xdd, thdd = w.accelerations(2.0 * limit, 1.0, 1.0 / w.radius)
    assert xdd == pytest.approx(0.3 * GRAVITY)  # kinetic friction carries the mass
    assert w.radius * thdd > xdd  # the wheel spins up faster than it rolls: slip grows


@pytest.mark.parametrize("kwargs, match", [
    ({"mass": 0.0}, "mass = 0.0"), ({"friction": -1.0}, "friction = -1.0"),
    ({"radius": float("nan")}, "radius = nan"),
])
def test_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        WheelDynamics(**({"mass": 1.0, "inertia": 0.1, "radius": 0.2} | kwargs))


def _coulomb_integration(w, torque, on_time, t_end):
    """Direct integration of m ẍ = F, J θ̈ = τ − F R with Coulomb F = μN sign(R θ̇ − ẋ),
    stopped at re-grip (event R θ̇ − ẋ = 0 after the pulse); written from the two
    equations of motion, not from SlipPulse."""
    from scipy.integrate import solve_ivp
    mu_n = w.friction * w.normal

    def f(t, y):
        tau = torque if t < on_time else 0.0
        return [y[1], mu_n / w.mass, (tau - mu_n * w.radius) / w.inertia]

    def regrip(t, y):
        return w.radius * y[2] - y[1] if t > on_time else 1.0
    regrip.terminal = True
    t_eval = np.linspace(0, t_end, 400)
    sol = solve_ivp(f, (0, t_end), [0, 0, 0], events=regrip, rtol=1e-11, atol=1e-12,
                    t_eval=t_eval, max_step=1e-3)
    return sol


def test_slip_pulse_matches_direct_coulomb_integration():
    w = WheelDynamics(mass=2.0, inertia=0.017, radius=0.15, friction=1.0)
    pulse = SlipPulse(w, 1.1 * w.max_rolling_torque, 0.2)
    sol = _coulomb_integration(w, pulse.torque, 0.2, 1.0)
    # re-grip time: event located to solver precision (1e-9 s scale); 1e-7 s asserted
    assert pulse.regrip_time == pytest.approx(sol.t_events[0][0], abs=1e-7)
    ref = pulse.state(sol.t)
    assert ref[:, 0] == pytest.approx(sol.y[0], abs=1e-8)
    assert ref[:, 1] == pytest.approx(sol.y[1], abs=1e-8)
    assert ref[:, 2] == pytest.approx(sol.y[2], abs=1e-7)
    # sliding accelerations against the two equations with F = μN
    assert pulse.linear_acceleration == pytest.approx(GRAVITY)
    assert pulse.spin_acceleration == pytest.approx(
        (pulse.torque - 2.0 * GRAVITY * 0.15) / 0.017)
    # after re-grip it rolls: R θ̇ = ẋ at constant speed
    late = pulse.state(np.array([pulse.regrip_time + 0.5]))[0]
    assert late[1] == pytest.approx(0.15 * late[2])


def test_slip_pulse_rejects_a_torque_that_rolls():
    w = WheelDynamics(mass=2.0, inertia=0.017, radius=0.15)
    with pytest.raises(ValueError, match=r"torque = 1.0 N·m does not slip; valid range is"):
        SlipPulse(w, 1.0, 0.1)
