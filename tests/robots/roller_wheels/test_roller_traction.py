"""Traction-limited acceleration against closed forms derived by hand for mecanum4."""

import math

import numpy as np
import pytest

from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.roller_traction import acceleration_time

A, W, M, IZ, MU, G = 0.15, 0.12, 4.0, 0.05, 0.8, 9.81
LAY = ok.mecanum_layout(0.05, A, W)
LOADS = np.full(4, M * G / 4)


@pytest.mark.parametrize(("twist", "rate"), [
    # Along x or y all four wheels push at 45°: a = μ g / √2.
    ((0.3, 0.0, 0.0), MU * G / math.sqrt(2)),
    ((0.0, -0.3, 0.0), MU * G / math.sqrt(2)),
    # Along a diagonal only the two wheels whose rollers lie along it: a = μ g / 2.
    ((0.3 / math.sqrt(2), 0.3 / math.sqrt(2), 0.0), MU * G / 2),
    # On the spot: four moments μ (m g / 4)(a + w)/√2: α = μ m g (a + w) / (√2 I_z).
    ((0.0, 0.0, 1.0), MU * M * G * (A + W) / (math.sqrt(2) * IZ)),
])
def test_closed_forms(twist, rate):
    speed = np.hypot(twist[0], twist[1]) or abs(twist[2])
    t = acceleration_time(LAY, M, IZ, LOADS, MU, np.array(twist))
    assert t == pytest.approx(speed / rate, rel=1e-6)


def test_zero_twist_takes_no_time():
    assert acceleration_time(LAY, M, IZ, LOADS, MU, np.zeros(3)) == 0.0


def test_omni_wheels_cannot_push_sideways_of_their_rollers():
    # Omni rollers (γ = 0) on three wheels all at β = 0 push only along x: y is out of reach.
    lay = ok.WheelLayout(np.array([[0.1, 0.0], [0.0, 0.1], [0.0, -0.1]]), np.zeros(3),
                         np.zeros(3), np.full(3, 0.03))
    with pytest.raises(ValueError, match="cannot accelerate"):
        acceleration_time(lay, M, IZ, np.full(3, 10.0), MU, np.array([0.0, 0.3, 0.0]))


@pytest.mark.parametrize(("kwargs", "match"), [({"mass": 0.0}, "mass"),
                                               ({"friction": -1.0}, "friction"),
                                               ({"normal_forces": np.ones(3)}, "normal")])
def test_bad_input_is_named(kwargs, match):
    args = {"layout": LAY, "mass": M, "yaw_inertia": IZ, "normal_forces": LOADS,
            "friction": MU, "twist": np.array([0.3, 0.0, 0.0])} | kwargs
    with pytest.raises(ValueError, match=match):
        acceleration_time(**args)
