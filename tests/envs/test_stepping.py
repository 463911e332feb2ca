"""The environments' recording-free physics loop (envs/stepping.py) and the action scale."""

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.drive import make
from wmr_mujoco.envs.episode import Episode, box_scale
from wmr_mujoco.envs.stepping import Stepper
from wmr_mujoco.sim.stepping import SimulationDivergedError

# A steered robot (servoed steering through the command map's controller), a holonomic
# one (a linear map), and the Whipple bicycle (torques, extras, RK4-free but no settling).
CASES = [("tricycle", [(0.4, 0.3), (0.5, -0.2), (0.2, 0.0)]),
         ("omni3", [(0.2, 0.1, 0.5), (-0.1, 0.2, -0.3), (0.0, 0.0, 0.0)]),
         ("whipple", [(0.5, 0.1), (0.0, -0.2), (0.3, 0.0)])]


@pytest.mark.parametrize("robot, commands", CASES)
def test_the_stepper_is_the_stepping_api_bit_for_bit(robot, commands):
    # Same model, same start, same commands: the stepper runs the same MuJoCo calls on the
    # same controls as robot.step, so every number is equal, not merely close.
    ref = make(robot, control_period=0.02)
    ref.reset(pose=(0.3, -0.2, 1.0), seed=3)
    expected = [ref.step(c) for c in commands]
    robot_ = make(robot, control_period=0.02)
    robot_.reset(pose=(0.3, -0.2, 1.0), seed=3)
    stepper = Stepper(robot_)
    stepper.start(1.0)
    for c, want in zip(commands, expected, strict=True):
        got = stepper.step(list(c))
        np.testing.assert_array_equal(got.pose, want.pose)
        np.testing.assert_array_equal(got.twist, want.twist)
        np.testing.assert_array_equal(got.wheel_rates, want.wheel_rates)
        assert got.time == pytest.approx(float(want.time), abs=1e-12)  # a sum of timesteps
        assert dict(got.extra) == dict(want.extra)
    np.testing.assert_array_equal(robot_.data.qpos, ref.data.qpos)
    np.testing.assert_array_equal(got.wheel_contacts, want.wheel_contacts)
    np.testing.assert_array_equal(got.steer_angles, want.steer_angles)


def test_the_heading_is_unwrapped_across_pi():
    # Turning in place past ψ = π: the snapshot's heading keeps growing (like RobotState's),
    # it does not jump by 2π.
    robot = make("diffdrive", control_period=0.02)
    robot.reset(pose=(0.0, 0.0, 3.0))
    stepper = Stepper(robot)
    headings = [stepper.start(3.0).xyh[2]]
    for _ in range(40):  # ~1 rad/s for 0.8 s: through π
        headings.append(stepper.step([0.0, 1.0]).xyh[2])
    assert headings[-1] > math.pi + 0.3
    assert max(abs(np.diff(headings))) < 0.1  # 1 rad/s · 0.02 s, with margin for the servo


def test_an_old_snapshot_refuses_the_live_readings():
    robot = make("diffdrive", control_period=0.02)
    robot.reset()
    stepper = Stepper(robot)
    first = stepper.start(0.0)
    assert first.wheel_contacts.all()  # the latest, at rest on its wheels
    stepper.step([0.1, 0.0])
    with pytest.raises(RuntimeError, match="no longer"):
        _ = first.wheel_contacts
    with pytest.raises(RuntimeError, match="no longer"):
        _ = first.steer_angles


def test_a_divergence_is_reported_not_returned():
    ep = Episode("diffdrive", "GoToGoal")
    ep.reset(np.random.default_rng(0))
    ep.robot.data.qvel[:] = 1e12  # MuJoCo flags a huge velocity within the next timestep
    with pytest.raises(SimulationDivergedError):
        ep.step(np.zeros(2, np.float32))


@pytest.mark.parametrize("low, high", [(-1.0, 1.0), (0.1, 0.7), (-0.3, 1e-300),
                                       (-2.0 / 3.0, 1.0 / 3.0), (5.0, 5.0)])
def test_box_scale_keeps_every_action_inside_the_box(low, high):
    (c,), (h,) = box_scale(np.array([low]), np.array([high]))
    for a in (-1.0, -0.999999, -1e-17, 0.0, 0.3, 1.0):
        assert low <= c + h * a <= high
    # Shrunk by rounding at most: the ends reach the limits to a few ulps.
    assert c + h == pytest.approx(high, rel=1e-15, abs=1e-15)
    assert c - h == pytest.approx(low, rel=1e-15, abs=1e-15)


def test_an_rk4_model_steps_whole_timesteps():
    # RK4 cannot be split into mj_step1/mj_step2: the stepper then runs mj_step(n) and
    # brings the frames and velocities up to date; the state equals a plain mj_step(n)'s.
    robot = make("diffdrive", control_period=0.02)
    robot.model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    robot.reset()
    stepper = Stepper(robot)
    stepper.start(0.0)
    twin = mujoco.MjData(robot.model)
    mujoco.mj_copyData(twin, robot.model, robot.data)
    got = stepper.step([0.3, 0.2])
    twin.ctrl[:] = robot.data.ctrl
    mujoco.mj_step(robot.model, twin, stepper.nstep)
    np.testing.assert_array_equal(robot.data.qpos, twin.qpos)
    mujoco.mj_forward(robot.model, twin)
    np.testing.assert_array_equal(got.xyh[:2], twin.site_xpos[robot.reader.site][:2])
