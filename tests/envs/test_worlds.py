"""The worlds' physics and reading on arrays (``envs.worlds``)."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco.envs.vector import WmrVectorEnv


def _twists(worlds):
    """Each world's body-frame ``(u, v, r)`` read by MuJoCo from its data now."""
    out = []
    for s in worlds.steppers:
        vel = np.zeros(6)
        mujoco.mj_objectVelocity(s.model, s.data, mujoco.mjtObj.mjOBJ_SITE, s.site, vel, 1)
        out.append(vel[[3, 4, 2]])
    return np.array(out)


@pytest.mark.parametrize("robot", ["disc", "bicycle"])  # ctrl = W u; servo channels first
def test_twists_read_with_the_physics_are_the_datas_twists(robot):
    # The inlined physics reads each world's twist right after its step; a step of some
    # worlds only (an autoreset) leaves it to the reading. Either way the reading gives
    # each world's twist as MuJoCo computes it from that world's data (exactly: the same
    # call on the same data).
    env = WmrVectorEnv(robot, "FollowPath", num_envs=3, batched=True)
    env.reset(seed=1)
    worlds = env.engine.worlds
    assert worlds._inline is not None
    actions = np.random.default_rng(2).uniform(-1, 1, (5, 3, env.single_action_space.shape[0]))
    for k, a in enumerate(actions):
        active = np.array([True, k % 2 == 0, True]) if k >= 3 else None
        worlds.push(a, active)
        assert worlds._twists is (active is None)
        s = worlds.read()
        assert not worlds._twists
        rows = slice(None) if active is None else active
        assert np.array_equal(s.uvr[rows], _twists(worlds)[rows]), k
