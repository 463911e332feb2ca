import numpy as np
import pytest

from wmr_mujoco.analytic.wheel_dynamics import GRAVITY, WheelDynamics


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
