import numpy as np
import pytest
from absl.testing import absltest
from dm_env import test_utils

from wmr_mujoco import suite


def _spec_test(robot: str, task: str) -> type:
    """dm_env's own checks (specs against every observation, reward and discount, over
    resets and action sequences) on one task, as a TestCase of its own."""
    def make_object_under_test(self):
        return suite.load(robot, task, task_kwargs={"random": 0})

    return type(f"SpecTest_{robot}_{task}", (test_utils.EnvironmentTestMixin,
                                              absltest.TestCase),
                {"make_object_under_test": make_object_under_test})


# One TestCase per task of ALL_TASKS (pytest collects them from the module's names).
for _robot, _task in suite.ALL_TASKS:
    _case = _spec_test(_robot, _task)
    globals()[_case.__name__] = _case


@pytest.mark.parametrize("robot, task", suite.ALL_TASKS)
def test_specs_hold_over_an_episode(robot, task):
    env = suite.load(robot, task, task_kwargs={"random": 1, "time_limit": 0.5})
    obs_spec, act_spec = env.observation_spec(), env.action_spec()
    timestep = env.reset()
    assert timestep.first()
    steps = 0
    while True:
        for key, spec in obs_spec.items():
            spec.validate(timestep.observation[key])
        if timestep.last():
            break
        timestep = env.step(act_spec.generate_value() + 0.3)
        steps += 1
        assert np.isfinite(timestep.reward)
    limit = round(0.5 / env.control_timestep())
    info = env.task.reward_terms(env.physics)
    if timestep.discount == 0.0:
        # Ended by the task (the Whipple bicycle falls under a constant steer torque).
        assert steps < limit and (info["failed"] or info["is_success"])
    else:
        # A 0.5-s episode truncates after 0.5 s / control period steps, discount 1.
        assert steps == limit and timestep.discount == 1.0


def test_control_timestep_is_the_robot_control_period():
    env = suite.load("omni3", "FollowPath")
    assert env.control_timestep() == pytest.approx(0.02)
    assert env.physics.model.opt.timestep == pytest.approx(0.001)


def test_physics_shares_the_robot_data():
    env = suite.load("diffdrive", "FollowPath", task_kwargs={"random": 3})
    env.reset()
    env.step(np.array([0.5, 0.0]))
    robot = env.task.episode.robot
    np.testing.assert_array_equal(env.physics.data.qpos, robot.data.qpos)
    assert env.physics.data.time == robot.data.time > 0


def test_seeded_episodes_repeat():
    a = suite.load("diffdrive", "GoToGoal", task_kwargs={"random": 5}).reset().observation
    b = suite.load("diffdrive", "GoToGoal", task_kwargs={"random": 5}).reset().observation
    np.testing.assert_array_equal(a["goal_xy"], b["goal_xy"])


@pytest.mark.parametrize("robot, task, kwargs, match", [
    ("tank", "GoToGoal", None, "valid robots are"),
    ("diffdrive", "Park", None, "its tasks: GoToGoal, FollowPath"),
    ("diffdrive", "GoToGoal", {"speed": 1.0}, "valid options"),
])
def test_bad_names_are_listed(robot, task, kwargs, match):
    with pytest.raises(ValueError, match=match):
        suite.load(robot, task, task_kwargs=kwargs)


def test_time_limit_comes_from_the_task():
    with pytest.raises(ValueError, match="come from the task"):
        suite.load("diffdrive", "GoToGoal", environment_kwargs={"time_limit": 3})


if __name__ == "__main__":
    absltest.main()
