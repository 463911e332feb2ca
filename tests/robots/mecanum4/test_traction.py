"""The step rise time read from the compiled mecanum4, against hand-derived closed forms."""

import math

import numpy as np
import pytest

from wmr_mujoco.models.loading import load
from wmr_mujoco.models.params_mecanum import MecanumParams
from wmr_mujoco.robots.mecanum4.traction import step_acceleration_time


def test_rise_time_along_x_uses_the_model_mass_only():
    # Along x: a = μ g / √2, independent of the mass (it cancels): T = V / a.
    p = MecanumParams()
    t = step_acceleration_time(load("mecanum4"), p, np.array([0.3, 0.0, 0.0]))
    assert t == pytest.approx(0.3 / (p.sim.friction * 9.81 / math.sqrt(2)), rel=1e-6)


def test_yaw_rise_is_bounded_by_the_box_inertia():
    # The chassis alone (a box) gives a smaller yaw inertia than the whole robot, so the
    # true rise time exceeds the one computed with the box's I_z.
    p = MecanumParams()
    length, width = 2 * p.half_length + p.wheel_radius, 2 * p.half_track
    i_box = p.chassis_mass * (length**2 + width**2) / 12
    a = p.half_length + p.half_track
    t_box = 1.0 / (p.sim.friction * p.total_mass * 9.81 * a / (math.sqrt(2) * i_box))
    assert step_acceleration_time(load("mecanum4"), p, np.array([0.0, 0.0, 1.0])) > t_box
