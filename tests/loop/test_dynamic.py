"""The ``"dynamic"`` backend: the Lagrange model stepped like the robot, and clear refusals."""

from __future__ import annotations

import numpy as np
import pytest

from wmr_mujoco.drive import make
from wmr_mujoco.robots import ROBOTS
from wmr_mujoco.robots.mecanum4 import TORQUE_AHEAD, TORQUE_DURATION
from wmr_mujoco.robots.mecanum4.dynamics import VELOCITY_PCT


def test_mecanum4_dynamic_backend_beside_the_physics_under_the_same_torques() -> None:
    # The straight-ahead torque run of mecanum4's validation ("torque ahead"), stepped
    # through both backends: the body velocity within the robot's requirement on its
    # Lagrange model (% of the peak speed), the one its DYNAMIC scenario is judged on.
    dyn = make("mecanum4", backend="dynamic", control_period=0.02)
    phys = make("mecanum4", backend="mujoco", control_period=0.02, mode="torque")
    assert dyn.command_space.shape == phys.command_space.shape == (4,)
    assert dyn.backend == "dynamic" and dyn.mode == "torque"
    dyn.reset()
    phys.reset()
    for _ in range(round(TORQUE_DURATION / 0.02)):
        a = dyn.step(np.array(TORQUE_AHEAD))
        b = phys.step(np.array(TORQUE_AHEAD))
    peak = abs(a.twist[0])
    assert peak > 0.05  # it accelerated (a = 4τ/(R M_eff) over 2 s: tenths of m/s)
    target = ROBOTS["mecanum4"].targets[VELOCITY_PCT].value
    assert np.max(np.abs(a.twist - b.twist)) <= target / 100 * peak
    assert a.pose[0] == pytest.approx(b.pose[0], rel=target / 100)
    assert a.wheel_contacts.all() and a.steer_angles.shape == (0,)


def test_robots_without_a_planar_lagrange_model_name_their_backends() -> None:
    with pytest.raises(ValueError, match="no Lagrange model.*its backends: mujoco, kinematic"):
        make("diffdrive", backend="dynamic")
    # The disc's single-wheel model is (distance, speed) along a fixed heading.
    with pytest.raises(ValueError, match="planar pose"):
        make("disc", backend="dynamic")
    with pytest.raises(ValueError, match="backend"):
        make("diffdrive", backend="lagrange")
    with pytest.raises(ValueError, match="mode='torque' only"):
        make("mecanum4", backend="dynamic", mode="wheels")
