import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import wmr_mujoco.envs as wenvs
from wmr_mujoco.envs import ENV_IDS, WmrEnv
from wmr_mujoco.envs.randomization import Bands


def test_every_drivable_robot_has_its_environments():
    from wmr_mujoco.drive import drivable

    assert "wmr/DiffDrive-GoToGoal-v0" in ENV_IDS
    assert {i.split("/")[1].split("-")[0] for i in ENV_IDS} == {
        wenvs.profile(r).stem for r in drivable()}


# The observations are physical quantities without a hard bound (the Box is ±inf, as in
# Gymnasium's own MuJoCo environments): check_env's two warnings about that are expected.
@pytest.mark.filterwarnings("ignore:.*Box observation space m.*infinity")
@pytest.mark.parametrize("env_id", ENV_IDS)
def test_check_env(env_id):
    env = gym.make(env_id).unwrapped
    check_env(env, skip_render_check=False)
    env.close()


def test_render_rgb_array():
    env = gym.make("wmr/DiffDrive-FollowPath-v0", render_mode="rgb_array", width=64,
                   height=48)
    env.reset(seed=0)
    frame = env.render()
    assert frame.shape == (48, 64, 3) and frame.dtype == np.uint8
    assert frame.std() > 0  # not a blank frame
    env.close()


def test_human_mode_without_display_is_a_clear_error(monkeypatch):
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    with pytest.raises(RuntimeError, match="needs a display"):
        WmrEnv("diffdrive", "GoToGoal", render_mode="human")


def test_same_seed_same_episode():
    env = gym.make("wmr/Omni3-FollowPath-v0")
    a, _ = env.reset(seed=4)
    step_a = env.step(np.array([0.3, -0.2, 0.1]))[0]
    b, _ = env.reset(seed=4)
    step_b = env.step(np.array([0.3, -0.2, 0.1]))[0]
    np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(step_a, step_b)
    c, _ = env.reset(seed=5)
    assert not np.array_equal(a, c)


def test_info_carries_the_reward_terms():
    env = gym.make("wmr/DiffDrive-GoToGoal-v0")
    env.reset(seed=0)
    _, reward, _, _, info = env.step(np.array([0.5, 0.0]))
    assert set(info["reward_terms"]) == {"progress", "heading", "effort", "success", "failure"}
    assert reward == pytest.approx(sum(info["reward_terms"].values()))


@pytest.mark.parametrize("action, match", [
    (np.zeros(3), r"shape \(3,\); expected \(2,\)"),
    (np.array([np.nan, 0.0]), "not finite"),
    (np.array([np.inf, 0.0]), "not finite"),
    ("fast", "not numeric"),
    (np.array([1 + 1j, 0.0]), "not numeric"),  # complex: numpy would drop the imaginary part
    (np.array([np.nan, 0.0], np.float32), "not finite"),  # float32, as policies give
])
def test_bad_actions_are_refused_before_stepping(action, match):
    env = gym.make("wmr/DiffDrive-GoToGoal-v0")
    env.reset(seed=0)
    robot = env.unwrapped.robot
    qpos, t = robot.data.qpos.copy(), robot.data.time
    with pytest.raises(ValueError, match=match):
        env.step(action)
    np.testing.assert_array_equal(robot.data.qpos, qpos)
    assert robot.data.time == t
    obs = env.step(np.zeros(2))[0]  # still usable, and finite
    assert np.all(np.isfinite(obs))


def test_actions_beyond_one_are_clipped_to_the_command_limits():
    env = WmrEnv("diffdrive", "GoToGoal")
    env.reset(seed=0)
    env.step(np.array([5.0, 0.0]))
    np.testing.assert_array_equal(env.episode.last_action, [1.0, 0.0])
    high = env.robot.command_space.high
    np.testing.assert_allclose(env.episode.command(np.ones(2)), high)


@pytest.mark.parametrize("kwargs, match", [
    ({"robot": "tank", "task": "GoToGoal"}, "valid robots are: .*diffdrive"),
    ({"robot": "disc_free", "task": "GoToGoal"}, "no natural command.*diffdrive"),
    ({"robot": "diffdrive", "task": "StayUpright"}, "its tasks: GoToGoal, FollowPath"),
    ({"robot": "diffdrive", "task": "GoToGoal", "mode": "torque"}, "valid modes: command, "),
    ({"robot": "diffdrive", "task": "GoToGoal", "render_mode": "ascii"}, "valid: None"),
    ({"robot": "diffdrive", "task": "GoToGoal", "task_kwargs": {"goal": 1}}, "valid options"),
    ({"robot": "diffdrive", "task": "GoToGoal", "width": 10**6}, r"\[16, 4096\]"),
])
def test_bad_arguments_name_the_valid_ones(kwargs, match):
    with pytest.raises(ValueError, match=match):
        WmrEnv(**kwargs)


def test_unknown_make_options_and_reset_options_are_named():
    with pytest.raises(TypeError, match=r"unknown option\(s\) \['randomise'\]; valid: mode, "
                       "randomize"):
        gym.make("wmr/DiffDrive-GoToGoal-v0", randomise=True)
    env = gym.make("wmr/DiffDrive-GoToGoal-v0")
    with pytest.raises(ValueError, match=r"takes no options, got \['goal'\]"):
        env.reset(seed=0, options={"goal": (1.0, 0.0, 0.0)})


def test_a_loosely_typed_robot_is_the_registry_robot():
    # The registry's lookup (any case, a unique prefix) names the robot; the environment
    # uses the registry name, not the typed one.
    assert WmrEnv("DiffDriv", "GoToGoal").robot.spec.name == "diffdrive"


@pytest.mark.parametrize("task, options, match", [
    ("GoToGoal", {"max_distance": 6.0}, "max_distance < arena"),
    ("GoToGoal", {"arena": 1e9, "max_distance": 2.0}, "above the 1000 m"),
    ("FollowPath", {"path_length": 1e12}, "above the 1000 m"),  # 5e13 path points
])
def test_task_sizes_are_checked_before_any_allocation(task, options, match):
    with pytest.raises(ValueError, match=match):
        WmrEnv("diffdrive", task, task_kwargs=options)


def test_wheels_mode_commands_the_wheel_servos():
    env = WmrEnv("diffdrive", "GoToGoal", mode="wheels")
    assert env.robot.command_space.names == ("left_wheel", "right_wheel")
    env.reset(seed=0)
    for _ in range(25):  # 0.5 s, many servo time constants (kv = 10 N m s, J ≈ 0.01)
        obs = env.step(np.array([0.5, 0.5]))[0]
    rates = obs[-4:-2]  # wheel_rates block, before last_action
    np.testing.assert_allclose(rates, 0.5 * env.robot.command_space.high, rtol=0.05)


def test_randomization_is_off_by_default_and_seeded_when_on():
    plain = WmrEnv("diffdrive", "GoToGoal")
    assert plain.reset(seed=0)[1]["randomization"] == {}
    env = WmrEnv("diffdrive", "GoToGoal", randomize=Bands(friction=(0.5, 0.6)))
    f1 = env.reset(seed=1)[1]["randomization"]["friction"]
    f2 = env.reset(seed=1)[1]["randomization"]["friction"]
    f3 = env.reset(seed=2)[1]["randomization"]["friction"]
    assert f1 == f2 != f3 and 0.5 <= f1[0] <= 0.6
    assert env.robot.model.geom_friction[0, 0] == pytest.approx(f3[0])
    mapped = WmrEnv("diffdrive", "GoToGoal", randomize={"friction": (0.5, 0.6), "mass": None})
    drawn = mapped.reset(seed=1)[1]["randomization"]
    assert drawn["friction"] == f1 and "mass" not in drawn and "servo_gain" in drawn
    with pytest.raises(ValueError, match="physical range"):
        WmrEnv("diffdrive", "GoToGoal", randomize={"friction": (0.0, 0.6)})


@pytest.mark.parametrize("vectorization_mode", ["sync", "async"])
def test_make_vec(vectorization_mode):
    envs = gym.make_vec("wmr/DiffDrive-GoToGoal-v0", num_envs=2,
                        vectorization_mode=vectorization_mode)
    obs, _ = envs.reset(seed=[0, 1])
    assert obs.shape == (2, 12)
    assert not np.array_equal(obs[0], obs[1])
    for _ in range(3):
        obs, reward, *_ = envs.step(envs.action_space.sample())
    assert obs.shape == (2, 12) and reward.shape == (2,)
    assert np.all(np.isfinite(obs))
    envs.close()


README_EXAMPLE = """
import gymnasium as gym
import wmr_mujoco.envs  # registers wmr/<Robot>-<Task>-v0 for every robot with actuators
env = gym.make("wmr/DiffDrive-GoToGoal-v0", render_mode="rgb_array", randomize=True)
obs, info = env.reset(seed=0)
obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
"""


def test_readme_example_runs_as_written():
    scope = {}
    exec(compile(README_EXAMPLE, "README", "exec"), scope)
    assert scope["obs"].shape == (12,) and set(scope["info"]["reward_terms"]) >= {"progress"}
    scope["env"].close()


def test_step_before_reset_is_refused():
    # Registered without Gymnasium's order-enforcing wrapper: the environment refuses it.
    env = gym.make("wmr/DiffDrive-GoToGoal-v0")
    with pytest.raises(RuntimeError, match=r"call reset\(\) before step\(\)"):
        env.step(np.zeros(2))
