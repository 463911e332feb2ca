"""The native vector environment (``gymnasium.make_vec`` default mode)."""

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.vector import AutoresetMode

import wmr_mujoco.envs  # noqa: F401  (registers the ids)
from wmr_mujoco.envs.batched import Batched
from wmr_mujoco.envs.serial import Serial
from wmr_mujoco.envs.vector import BATCHED_FROM, WmrVectorEnv, check_actions

#: Few-step episodes, so that the runs below end episodes (failures and time limits) and
#: so exercise the autoreset paths.
SHORT = {"task_kwargs": {"time_limit": 0.3}}


def test_make_vec_defaults_to_the_native_vector_env():
    envs = gym.make_vec("wmr/Disc-GoToGoal-v0", num_envs=3)
    assert isinstance(envs, WmrVectorEnv)
    assert envs.metadata["autoreset_mode"] is AutoresetMode.NEXT_STEP
    assert envs.observation_space.shape == (3, envs.single_observation_space.shape[0])
    assert envs.action_space.shape == (3, 2)
    # Each world its own model: randomisation is drawn per world.
    assert len({id(e.robot.model) for e in envs.envs}) == 3


def _same(a, b):
    """Infos equal key for key (arrays exactly, dtypes included), in the same order."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and list(a) == list(b)
        for k in a:
            _same(a[k], b[k])
    elif isinstance(a, np.ndarray) and a.dtype == object:
        assert a.shape == b.shape
        for x, y in zip(a, b, strict=True):
            _same(x, y)
    elif isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and np.array_equal(a, b)
    else:
        assert a == b


@pytest.mark.parametrize("n", [3, BATCHED_FROM])  # world by world, then batched
@pytest.mark.parametrize("mode", list(AutoresetMode))
@pytest.mark.parametrize("env_id", ["wmr/Disc-FollowPath-v0", "wmr/Whipple-StayUpright-v0",
                                    "wmr/DiffDrive-GoToGoal-v0", "wmr/Bicycle-FollowPath-v0",
                                    "wmr/Mecanum4-GoToGoal-v0",
                                    "wmr/Omni3Reduced-FollowPath-v0",
                                    "wmr/SingleSteer-GoToGoal-v0", "wmr/Tricycle-GoToGoal-v0"])
def test_native_equals_n_single_envs_with_the_same_seeds(env_id, mode, n):
    # Exact equality (no tolerance): world i's physics is the single environment's own
    # (its stepper's command map and mj_step calls on its own model), and the batched
    # reading, task and bookkeeping (envs.worlds, envs.tasks.arrays) are the scalar code's
    # floating-point operations in the same order, so every observation (float32), reward,
    # flag and info must be bit for bit those of Gymnasium's SyncVectorEnv over n single
    # environments seeded alike. Light and heavy robots, each task kind, every autoreset
    # mode, randomisation on, episodes ending (0.3 s) and so resets mixed with steps;
    # steering servos batched (bicycle, single steer; the tricycle's with its command map's
    # adjustment, world by world). Both paths: below BATCHED_FROM worlds each world through its single
    # environment (envs.serial), from it on the batched arrays (envs.batched).
    native = gym.make_vec(env_id, num_envs=n, autoreset_mode=mode, randomize=True, **SHORT)
    assert isinstance(native.engine, Batched if n >= BATCHED_FROM else Serial)
    sync = gym.make_vec(env_id, num_envs=n, vectorization_mode="sync", randomize=True,
                        vector_kwargs={"autoreset_mode": mode}, **SHORT)
    o1, i1 = native.reset(seed=11)
    o2, i2 = sync.reset(seed=11)
    assert np.array_equal(o1, o2) and o1.dtype == np.float32
    _same(i1, i2)
    rng = np.random.default_rng(0)
    ended = 0
    for _ in range(40):
        a = rng.uniform(-1.2, 1.2, native.action_space.shape)  # some beyond 1: clipped
        out1, out2 = native.step(a), sync.step(a)
        for x, y in zip(out1[:4], out2[:4], strict=True):
            assert x.dtype == y.dtype and np.array_equal(x, y)
        _same(out1[4], out2[4])
        done = out1[2] | out1[3]
        ended += int(done.sum())
        if mode is AutoresetMode.DISABLED and done.any():
            r1, r2 = native.reset(options={"reset_mask": done}), sync.reset(
                options={"reset_mask": done.copy()})
            assert np.array_equal(r1[0], r2[0])
            _same(r1[1], r2[1])
    assert ended >= n  # every world ended at least one episode (0.3 s time limit)


def test_next_step_autoreset():
    # Gymnasium 1.x's default: the step after an episode's end resets that world (its
    # action ignored): first observation of a new episode, reward 0, both flags false.
    envs = gym.make_vec("wmr/Disc-GoToGoal-v0", num_envs=2, **SHORT)
    envs.reset(seed=0)
    zero = np.zeros((2, 2))
    steps = 0
    while True:
        obs, reward, term, trunc, info = envs.step(zero)
        steps += 1
        if trunc.any() or term.any():
            break
    # Standing still: truncated at the 0.3 s limit (15 steps of 20 ms), both worlds at once.
    assert trunc.all() and steps == 15 and np.allclose(info["time"], 0.3)
    obs, reward, term, trunc, info = envs.step(np.full((2, 2), np.float32(0.7)))
    assert np.array_equal(reward, [0.0, 0.0]) and not term.any() and not trunc.any()
    assert "randomization" in info and "time" not in info  # the reset's info
    # The new episode starts at rest at its new goal: the single env's next reset.
    single = gym.make("wmr/Disc-GoToGoal-v0", **SHORT)
    single.reset(seed=0)
    for _ in range(15):
        single.step(np.zeros(2))
    assert np.array_equal(obs[0], single.reset()[0])


def test_disabled_autoreset_refuses_to_step_an_ended_world():
    envs = gym.make_vec("wmr/Disc-GoToGoal-v0", num_envs=2,
                        autoreset_mode=AutoresetMode.DISABLED, **SHORT)
    envs.reset(seed=0)
    for _ in range(15):
        envs.step(np.zeros((2, 2)))
    with pytest.raises(RuntimeError, match=r"world\(s\) \[0, 1\] ended"):
        envs.step(np.zeros((2, 2)))
    envs.reset(options={"reset_mask": np.array([True, True])})
    envs.step(np.zeros((2, 2)))


@pytest.mark.parametrize(("actions", "match"), [
    (np.zeros((3, 2)), r"shape \(3, 2\); expected \(2, 2\)"),
    (np.zeros(2), r"shape \(2,\); expected \(2, 2\)"),
    (np.array([[0.0, 0.0], [np.nan, 0.0]]), r"world\(s\) \[1\] are not finite"),
    (np.array([[np.inf, 0.0], [0.0, 0.0]]), r"world\(s\) \[0\] are not finite"),
    ([["a", "b"], ["c", "d"]], "not numeric"),
])
def test_bad_actions_are_refused_before_any_world_steps(actions, match):
    envs = gym.make_vec("wmr/Disc-GoToGoal-v0", num_envs=2)
    envs.reset(seed=0)
    with pytest.raises(ValueError, match=match):
        envs.step(actions)
    # No world moved: the next good step equals a fresh run's first step.
    fresh = gym.make_vec("wmr/Disc-GoToGoal-v0", num_envs=2)
    fresh.reset(seed=0)
    a = np.full((2, 2), 0.5)
    assert np.array_equal(envs.step(a)[0], fresh.step(a)[0])


def test_check_actions_clips_and_keeps_good_batches():
    assert check_actions(np.array([[0.5, -2.0]], np.float32), (1, 2)).tolist() == [[0.5, -1.0]]
    assert check_actions([[1, 0]], (1, 2)).tolist() == [[1.0, 0.0]]  # ints and lists are numbers


@pytest.mark.parametrize(("kwargs", "match"), [
    ({"num_envs": 0}, r"num_envs=0; valid: an integer in \[1, 256\]"),
    ({"num_envs": 2.5}, "num_envs=2.5"),
    ({"num_envs": 10**9}, "num_envs=1000000000"),  # refused before building any world
    ({"autoreset_mode": "sometimes"}, "autoreset_mode='sometimes'; valid: NextStep, "
                                       "SameStep, Disabled"),
    ({"colour": "red"}, r"unknown option\(s\) \['colour'\]"),
    ({"render_mode": "human"}, "one viewer per world"),
    ({"batched": "yes"}, r"batched='yes'; valid: True"),
])
def test_bad_arguments_are_named(kwargs, match):
    with pytest.raises((ValueError, TypeError), match=match):
        WmrVectorEnv("disc", "GoToGoal", **kwargs)


def test_reset_arguments_are_checked():
    envs = gym.make_vec("wmr/Disc-GoToGoal-v0", num_envs=2)
    with pytest.raises(ValueError, match="3 seeds for 2 worlds"):
        envs.reset(seed=[0, 1, 2])
    with pytest.raises(ValueError, match="only the option 'reset_mask'"):
        envs.reset(options={"speed": 1})
    with pytest.raises(ValueError, match=r"reset_mask"):
        envs.reset(options={"reset_mask": np.array([False, False])})
    with pytest.raises(RuntimeError, match=r"call reset\(\) before step\(\)"):
        envs.step(np.zeros((2, 2)))


def test_rgb_frames_per_world():
    envs = gym.make_vec("wmr/Disc-GoToGoal-v0", num_envs=2, render_mode="rgb_array",
                        width=64, height=48)
    envs.reset(seed=0)
    frames = envs.render()
    assert len(frames) == 2 and frames[0].shape == (48, 64, 3)
    envs.close()


def test_a_diverging_world_is_reported():
    from wmr_mujoco.sim.stepping import SimulationDivergedError

    envs = gym.make_vec("wmr/Disc-GoToGoal-v0", num_envs=3)
    envs.reset(seed=0)
    envs.envs[1].robot.data.qvel[:] = 1e300  # world 1 blows up in its next step
    with pytest.raises(SimulationDivergedError):
        envs.step(np.zeros((3, 2)))
