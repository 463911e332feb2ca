"""The ``"kinematic"`` backend against closed-form solutions of the models it integrates."""

from __future__ import annotations

import math

import numpy as np
import pytest

from wmr_mujoco.drive import make
from wmr_mujoco.robots.bicycle.params import BicycleParams
from wmr_mujoco.robots.tricycle import analytic as tricycle
from wmr_mujoco.robots.tricycle.params import TricycleParams

#: RK4 on the 2 ms timestep: global error O(Δt⁴), below 1e-9 m over 10 s for these smooth
#: models (``wmr_mujoco.analytic.integrate``); the runs here are 2 s.
RK4_TOL = 1e-9


def arc(pose: np.ndarray, u: float, v: float, r: float, t: float) -> np.ndarray:
    """Pose after ``t`` of a constant body twist: the circle through the start.

    In the start frame the body is at ``((u sin rt − v (1 − cos rt)) / r,
    (u (1 − cos rt) + v sin rt) / r)``, turned by ``rt``.
    """
    s, c = math.sin(r * t), math.cos(r * t)
    dx, dy = (u * s - v * (1 - c)) / r, (u * (1 - c) + v * s) / r
    cp, sp = math.cos(pose[2]), math.sin(pose[2])
    return np.array([pose[0] + cp * dx - sp * dy, pose[1] + sp * dx + cp * dy,
                     pose[2] + r * t])


def test_diffdrive_follows_the_unicycle_arc() -> None:
    robot = make("diffdrive", backend="kinematic")
    pose = np.array([0.5, -1.0, 2.0])
    robot.reset(pose)
    for _ in range(100):
        state = robot.step((0.6, -0.9))
    np.testing.assert_allclose(state.pose, arc(pose, 0.6, 0.0, -0.9, 2.0), atol=RK4_TOL)
    np.testing.assert_allclose(state.twist, (0.6, 0.0, -0.9), atol=1e-12)
    assert state.wheel_contacts.all()


def test_omni3_follows_the_body_twist_circle() -> None:
    robot = make("omni3", backend="kinematic")
    pose = np.array([-0.2, 0.3, -1.0])
    robot.reset(pose)
    twist = (0.3, -0.2, 1.1)
    for _ in range(100):
        state = robot.step(twist)
    # omni3's model steps exactly (SE(2) exponential): round-off only.
    np.testing.assert_allclose(state.pose, arc(pose, *twist, 2.0), atol=1e-12)
    np.testing.assert_allclose(state.twist, twist, atol=1e-12)


def test_bicycle_steers_like_the_servo_and_turns_at_v_tan_phi_over_l() -> None:
    robot = make("bicycle", backend="kinematic")
    robot.reset()
    p = BicycleParams()
    phi = 0.05  # below ω_max T = 3 rad/s × 0.02 s: reached in one period
    state = robot.step((2.0, phi))
    assert state.steer_angles[0] == pytest.approx(phi, abs=1e-12)
    state = robot.step((2.0, phi))
    assert state.twist[2] == pytest.approx(2.0 * math.tan(phi) / p.wheelbase, rel=1e-12)
    state = robot.step((2.0, 0.5))  # rate-limited: 0.06 rad per period
    assert state.steer_angles[0] == pytest.approx(phi + 0.06, abs=1e-12)


def test_tricycle_wheels_roll_about_the_common_icr() -> None:
    """Midpoint speed v as commanded; the free right and front wheels at the ICR rates of
    :mod:`wmr_mujoco.robots.tricycle.analytic` (``v_R = v (1 + k)``, ``v_F = v / cos φ``), which
    the backend gets from the wheel geometry of the compiled model."""
    robot = make("tricycle", backend="kinematic")
    robot.reset()
    p = TricycleParams()
    phi, v = 0.04, 0.8
    for _ in range(3):
        state = robot.step((v, phi))
    assert state.twist[0] == pytest.approx(v, rel=1e-12)
    v_left, v_right = tricycle.rear_wheel_speeds(v, phi, p.track, p.wheelbase)
    expected = [v_left / p.rear_wheel.radius, v_right / p.rear_wheel.radius,
                tricycle.front_wheel_speed(v, phi) / p.front_wheel.radius]
    np.testing.assert_allclose(state.wheel_rates, expected, rtol=1e-9)


@pytest.mark.parametrize("name", ["bicycle", "tricycle"])
def test_a_period_through_the_adapters_trajectory_is_rk4_step_after_step(name) -> None:
    """A model without an exact step but with a ``trajectory`` holds the input over the
    period's substeps through it: the floats of ``rk4_step`` step after step, to the bit
    (a turning state, so that every stage's heading and steering matter)."""
    from wmr_mujoco.analytic.integrate import rk4_step
    from wmr_mujoco.loop.kinematic import hold

    robot = make(name, backend="kinematic")
    assert robot._exact is None and hasattr(robot.adapter, "trajectory")
    assert robot.nstep > 1
    x = np.array([0.3, -0.2, 0.7, 0.25])
    u = np.array([1.3, 0.4])
    want = x
    for _ in range(robot.nstep):
        want = rk4_step(robot.adapter.rhs, want, u, robot.dt)
    assert hold(robot, x, u, "kinematic").tobytes() == want.tobytes()
