"""The environment benchmarks' shared loops: the recording, the bare and vector loops and
the paired measurement (no timing asserts)."""

import gymnasium as gym
import numpy as np
import pytest

from wmr_mujoco.bench import env_loops as el


def test_the_replayed_episode_is_a_solved_one():
    """The loops replay the scripted controller's episode: it ends in success, so the
    figures are those of a policy that drives the robot as the task wants."""
    env = gym.make("wmr/Whipple-StayUpright-v0")
    rec = el.record(env)
    # Not toppled: the whole 10 s episode at 100 Hz.
    assert len(rec.actions) == 1000 and rec.controls.shape == (1000, env.unwrapped.robot.model.nu)


def test_bare_and_vector_loops_step_the_same_physics():
    # The bare loop replays the controls that the episode's command map wrote; a vector
    # loop of 2 worlds (either path) steps the same actions: after the same steps every
    # world is in the bare loop's state, bit for bit (the same mj_step on the same inputs).
    env_id = "wmr/Disc-GoToGoal-v0"
    rec = el.record(gym.make(env_id))
    world = el.bare_world(env_id)
    bare = el.bare_loop([world], rec.controls)
    bare(30)
    for mode in ("serial", "batched"):
        vec = gym.make_vec(env_id, num_envs=2, autoreset_mode=gym.vector.AutoresetMode.DISABLED,
                           batched=mode == "batched")
        vec.reset(seed=[el.SEED] * 2)
        for a in rec.actions[:30]:
            vec.step(np.stack([a] * 2))
        for e in vec.envs:
            assert np.array_equal(e.robot.data.qpos, world[1].qpos), mode


def test_bad_vector_mode_is_named():
    with pytest.raises(ValueError, match="'async'; valid: native, serial, batched, sync"):
        el.vector_loop("wmr/Disc-GoToGoal-v0", 2, [], "async")


def test_paired_ratios_are_the_medians_of_the_round_ratios(monkeypatch):
    """Each round's ratio is its loop over the mean of its two bare runs; the figure is
    their median (0.5 here), not the ratio of the medians (180 / 200 = 0.9 here): a load
    that changes between rounds cancels within each round."""
    # rate() in call order, per round: bare first, loop, bare last.
    rounds = [(100.0, 40.0, 100.0), (300.0, 200.0, 500.0), (200.0, 180.0, 200.0)]
    calls = iter([v for r in rounds for v in r])
    monkeypatch.setattr(el, "rate", lambda run, seconds: next(calls))
    got = el.paired(lambda n: 0.0, {"loop": lambda n: 0.0}, 0.1, 3)
    assert got.ratios["loop"] == pytest.approx(0.5, rel=1e-15)  # 0.4, 0.5, 0.9
    assert got.rates == {"loop": 180.0} and got.bare == 200.0  # medians
    calls = iter([v for r in rounds for v in r])
    got = el.paired(lambda n: 0.0, {"loop": lambda n: 0.0}, 0.1, 3, {"loop": 4})
    assert got.ratios["loop"] == pytest.approx(4 * 0.5, rel=1e-15)  # every world's steps
