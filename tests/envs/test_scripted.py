import numpy as np
import pytest

from wmr_mujoco.envs import ENV_IDS, WmrEnv
from wmr_mujoco.envs.episode import Episode
from wmr_mujoco.envs.scripted import Scripted, run_episode


@pytest.mark.parametrize("env_id", ENV_IDS)
def test_scripted_controller_solves_a_few_episodes(env_id):
    # A few seeds per task here; the full rate (goal >= 95 %) is measured by
    # ``python -m wmr_mujoco.bench.env_success``.
    env = WmrEnv(*_robot_task(env_id))
    results = [run_episode(env.episode, np.random.default_rng(seed))[0] for seed in (0, 1, 2)]
    assert all(results)


def _robot_task(env_id):
    from gymnasium import spec

    kwargs = spec(env_id).kwargs
    return kwargs["robot"], kwargs["task"]


def test_standing_still_does_not_succeed():
    # The success criterion is not met by doing nothing (the test above can fail).
    env = WmrEnv("diffdrive", "GoToGoal", task_kwargs={"time_limit": 2.0})
    env.reset(seed=0)
    done = False
    while not done:
        _, _, term, trunc, info = env.step(np.zeros(2))
        done = term or trunc
    assert trunc and not info["is_success"]


def test_unknown_command_space_has_no_scripted_controller():
    ep = Episode("diffdrive", "GoToGoal", mode="wheels")
    with pytest.raises(ValueError, match="no scripted controller"):
        Scripted(ep)


def test_the_steering_law_reads_the_declared_steer_arm():
    # The kind follows the command's channel names and the registry entry's steer_arm,
    # and the arm is the robot's parameter of that name (no duck typing on the params).
    kinds = {}
    for robot in ("bicycle", "tricycle", "single_steer", "double_steer"):
        ctrl = Scripted(Episode(robot, "FollowPath"))
        kinds[robot] = ctrl.kind
        name = ctrl.ep.profile.steer_arm
        params = ctrl.ep.robot.spec.params_type()  # the robot's (default) parameters
        assert ctrl.arm == (getattr(params, name) if name else 0.0)
    assert kinds == {"bicycle": "car", "tricycle": "car", "single_steer": "wheel",
                     "double_steer": "double"}
    assert Scripted(Episode("bicycle", "FollowPath")).law.wheelbase == pytest.approx(1.05)


def test_a_steer_arm_that_is_not_a_parameter_is_named():
    from dataclasses import replace

    from wmr_mujoco.envs import scripted

    ep = Episode("bicycle", "FollowPath")
    ep.profile = replace(ep.profile, steer_arm="axle_gap")
    with pytest.raises(ValueError, match="steer_arm='axle_gap' is not a field"):
        scripted.Scripted(ep)
