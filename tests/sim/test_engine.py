"""The two engines: a Python ``mj_step`` loop and ``mujoco.rollout`` give the same states.

The reference is a plain ``mj_step`` loop written here; "the same" is bit for bit (both run
the same C step from the same state and warm start), so the comparisons are exact.
"""

import mujoco
import numpy as np
import pytest

from wmr_mujoco.sim.engine import STATE_SPEC, Engine, get_state, simulate, simulate_batch
from wmr_mujoco.sim.stepping import SimulationDivergedError

#: A driven ball on a plane: contact, friction and an actuator, cheap to step.
XML = """
<mujoco>
  <option timestep="0.002"/>
  <worldbody>
    <geom type="plane" size="5 5 0.1"/>
    <body pos="0 0 0.1">
      <freejoint/>
      <geom type="sphere" size="0.1" mass="1"/>
    </body>
    <body pos="1 0 0.3">
      <joint name="slide" type="slide" axis="1 0 0"/>
      <geom type="box" size="0.05 0.05 0.05" mass="0.5"/>
    </body>
  </worldbody>
  <actuator><motor joint="slide" gear="1"/></actuator>
</mujoco>
"""


@pytest.fixture
def model() -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(XML)


def _reference(model: mujoco.MjModel, controls: np.ndarray) -> np.ndarray:
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    out = [get_state(model, data)]
    for ctrl in controls:
        data.ctrl[:] = ctrl
        mujoco.mj_step(model, data)
        state = np.empty(mujoco.mj_stateSize(model, STATE_SPEC))
        mujoco.mj_getState(model, data, state, STATE_SPEC)
        out.append(state)
    return np.array(out)


@pytest.mark.parametrize("engine", list(Engine))
def test_engines_match_a_plain_step_loop(model, engine):
    controls = np.sin(np.linspace(0.0, 6.0, 150))[:, None]
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    states = simulate(model, data, controls, engine=engine.value)
    np.testing.assert_array_equal(states, _reference(model, controls))


def test_loop_calls_back_after_every_step(model):
    data = mujoco.MjData(model)
    seen = []
    simulate(model, data, np.zeros((7, 1)), engine="loop",
             on_step=lambda k: seen.append((k, data.time)))
    assert [k for k, _ in seen] == list(range(7))
    np.testing.assert_allclose([t for _, t in seen], 0.002 * np.arange(1, 8))


def test_batch_of_unequal_lengths_is_each_run_alone(model):
    start = mujoco.MjData(model)
    mujoco.mj_forward(model, start)
    controls = [np.full((40, 1), 2.0), np.linspace(-1.0, 1.0, 90)[:, None]]
    out = simulate_batch(model, start, controls, nthread=2)
    assert [len(s) for s in out] == [41, 91]
    for c, states in zip(controls, out, strict=True):
        np.testing.assert_array_equal(states, _reference(model, c))


def test_unknown_engine_is_refused(model):
    with pytest.raises(ValueError, match="unknown engine 'euler'; valid engines are: rollout, "
                                         "loop"):
        simulate(model, mujoco.MjData(model), np.zeros((1, 1)), engine="euler")


@pytest.mark.parametrize("engine", list(Engine))
def test_a_diverging_run_is_reported(model, engine, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # MuJoCo logs the warning to MUJOCO_LOG.TXT in the cwd
    data = mujoco.MjData(model)
    with pytest.raises(SimulationDivergedError):
        simulate(model, data, np.full((20, 1), 1e300), engine=engine)
