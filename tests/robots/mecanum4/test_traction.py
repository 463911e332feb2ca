"""The step models of the compiled mecanum4: rise time and stick–slip model parameters."""

import math

import numpy as np
import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.robots.mecanum4.collider import realised_twist
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.mecanum4.traction import step_acceleration_time, step_platform
from wmr_mujoco.robots.roller_wheels import pitch_averaged as pa
from wmr_mujoco.robots.roller_wheels.roller_stick_slip import step_response


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


def test_step_model_reads_the_drive_law_and_contact_from_the_model():
    # Every parameter from the compiled model, checked against the parameters it was
    # built from: servo gain and torque limit, floor friction, the wheel inertia at least
    # the rotor armature, the centre of mass at axle height within 2 mm (the chassis box
    # is centred on the axles; the rollers sit below them by symmetry), γ̄ on the wheels
    # that turn (docs/mecanum.md §3) and γ on the ones at rest (a diagonal).
    p = MecanumParams()
    plat, cmd = step_platform(load("mecanum4"), p, np.array([0.3, 0.3, 0.0]) / math.sqrt(2))
    assert (plat.servo_gain, plat.torque_limit) == (p.drive.wheel_kv,
                                                     p.drive.wheel_torque_limit)
    assert plat.friction == p.sim.friction
    assert plat.wheel_inertia > p.drive.wheel_armature
    assert plat.com_height == pytest.approx(p.wheel_radius, abs=2e-3)
    k = pa.mean_secant(math.pi / p.rollers_per_wheel)
    turning = np.abs(cmd) > 1e-9
    assert list(turning) == [False, True, True, False]
    np.testing.assert_allclose(np.abs(plat.layout.roller_angles),
                               np.where(turning, math.atan(k), math.pi / 4), rtol=1e-12)


@pytest.mark.parametrize("twist", [(0.0, 0.3, 0.0), (0.0, 0.0, 1.0)])
def test_step_model_settles_on_the_kinematic_model(twist):
    # After the rise the contacts stick on the effective rows, H_e ν = ω_cmd = H(γ) ν_cmd,
    # so ν is the kinematic model's twist (robots.mecanum4.collider.realised_twist, the
    # colliders' pitch mean, computed by least squares, not by integration); no load is
    # left on the servos (no rigid-body term without a turn while translating), so to the
    # settle criterion (1e-9 per 50 ms chunk against a servo time constant of a few ms).
    p = MecanumParams()
    nu = np.array(twist)
    plat, cmd = step_platform(load("mecanum4"), p, nu)
    r = step_response(plat, cmd, 2.0)
    np.testing.assert_allclose(r.twist[-1], realised_twist(p, nu), atol=1e-8)
    assert r.time[-1] < 0.5  # settled long before the run's end
