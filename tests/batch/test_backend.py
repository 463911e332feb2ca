"""Full-physics states rebuilt from qpos/qvel/act equal MuJoCo's own mj_getState."""

import mujoco
import numpy as np

import wmr_mujoco as wmr
from wmr_mujoco.batch.backend import full_states, state_segments
from wmr_mujoco.sim.engine import STATE_SPEC, get_state


def test_full_states_equal_mj_get_state():
    model = wmr.load("bicycle")
    data = mujoco.MjData(model)
    for _ in range(20):
        mujoco.mj_step(model, data)
    initial = get_state(model, data)
    expected, qpos, qvel, act = [initial], [data.qpos.copy()], [data.qvel.copy()], [data.act.copy()]
    for _ in range(5):
        mujoco.mj_step(model, data)
        expected.append(get_state(model, data))
        qpos.append(data.qpos.copy())
        qvel.append(data.qvel.copy())
        act.append(data.act.copy())
    got = full_states(model, initial, np.array(qpos), np.array(qvel), np.array(act))
    # time is t0 + k Δt, MuJoCo's sum of Δt: equal to rounding.
    seg = state_segments(model)
    np.testing.assert_allclose(got[:, seg["time"]], np.array(expected)[:, seg["time"]],
                               rtol=0, atol=1e-12)
    other = np.ones(got.shape[1], bool)
    other[seg["time"]] = False
    np.testing.assert_array_equal(got[:, other], np.array(expected)[:, other])
    assert got.shape[1] == mujoco.mj_stateSize(model, STATE_SPEC)
    assert seg["qpos"].stop - seg["qpos"].start == model.nq
