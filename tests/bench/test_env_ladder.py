"""The layer-by-layer cost of an environment step runs and reports (no timing asserts)."""

import numpy as np
import pytest

from wmr_mujoco.bench import env_ladder


def test_every_layer_is_timed_and_tabled():
    us = env_ladder.ladder("wmr/Disc-GoToGoal-v0", seconds=0.05, repeats=1)
    assert set(us) == set(env_ladder.LAYERS)
    assert all(v > 0 for v in us.values())
    row = env_ladder.table({"wmr/Disc-GoToGoal-v0": us}).splitlines()[-1]
    # One cell per layer, the layers after the first with what they add in brackets.
    assert row.startswith("| wmr/Disc-GoToGoal-v0 | ") and row.count("(+") + row.count(
        "(-") == len(env_ladder.LAYERS) - 1


def test_the_layers_replay_the_same_physics():
    # Every loop steps the recorded episode from the same reset, so after the same number
    # of steps each loop's robot is in the same state: bit for bit (the stepper splits the
    # same timesteps around mj_step1, and the recorded controls are the ones its command
    # map wrote), so that the layers differ only in the Python around the physics.
    runs, envs = env_ladder.ladder_loops("wmr/Disc-GoToGoal-v0")
    for run in runs.values():
        run(25)
    bare = envs["bare"].robot.data.qpos
    for name in env_ladder.LAYERS[1:]:
        assert np.array_equal(envs[name].robot.data.qpos, bare), name


def test_bad_arguments_exit_2(capsys):
    with pytest.raises(SystemExit) as exc:
        env_ladder.main(["--repeats", "0"])
    assert exc.value.code == 2 and "--repeats 0 (valid: 1 to 20)" in capsys.readouterr().err
    with pytest.raises(SystemExit) as exc:
        env_ladder.main(["wmr/Nope-v0"])
    assert exc.value.code == 2


def test_the_vector_layers_are_timed_per_world_step():
    us = env_ladder.ladder("wmr/Disc-FollowPath-v0", seconds=0.05, repeats=1, worlds=2)
    assert set(us) == set(env_ladder.VECTOR_LAYERS) and all(v > 0 for v in us.values())
    row = env_ladder.table({"wmr/Disc-FollowPath-v0": us}).splitlines()
    assert row[0].endswith("| vector | vector / bare |")
    assert row[-1].count("(+") + row[-1].count("(-") == len(env_ladder.VECTOR_LAYERS) - 1
