import warnings

import mujoco
import numpy as np
import pytest

from wmr_mujoco import load, set_actuation_mode
from wmr_mujoco.sim.stepping import SimulationDivergedError, check_healthy, rollout

from conftest import ACTUATED


@pytest.mark.parametrize("mode", ["rate", "torque"])
@pytest.mark.parametrize("robot", ACTUATED)
def test_random_in_range_controls_stay_healthy(robot, mode, rng):
    """2 s of random controls, redrawn every 0.1 s: no MuJoCo warning, no NaN."""
    model = load(robot)
    set_actuation_mode(model, mode)
    data = mujoco.MjData(model)
    lo, hi = model.actuator_ctrlrange.T
    draws = rng.uniform(lo, hi, size=(20, model.nu))
    traj = rollout(model, data, 2.0, lambda t: draws[min(int(t / 0.1), 19)])
    assert np.all(np.isfinite(traj))
    assert all(data.warning[i].number == 0 for i in range(len(data.warning)))


@pytest.mark.parametrize("key", ["rest", "rolling", "spinning", "leaning"])
def test_free_disc_keyframes_stay_healthy(key):
    model = load("disc_free")
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key(key).id)
    rollout(model, data, 2.0)
    assert data.qpos[2] > 0.0  # still above the floor


def test_divergence_is_reported_not_returned():
    model = load("disc")
    data = mujoco.MjData(model)
    data.qvel[0] = np.nan
    with pytest.raises(SimulationDivergedError, match="diverged at t=.*mjWARN_BADQVEL"):
        rollout(model, data, 0.1)


def test_check_healthy_reads_warnings():
    model = load("disc")
    data = mujoco.MjData(model)
    data.warning[mujoco.mjtWarning.mjWARN_CONTACTFULL].number = 1
    with pytest.raises(SimulationDivergedError, match="mjWARN_CONTACTFULL x1"):
        check_healthy(model, data)


@pytest.mark.parametrize("field", ["qpos", "qvel", "act"])
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_check_healthy_names_a_non_finite_field_without_a_warning(field, bad):
    """No MuJoCo warning, one non-finite entry: named, whichever field and value."""
    model = load("disc")  # it has an activation state (its steering servo's filter)
    data = mujoco.MjData(model)
    assert data.act.size
    getattr(data, field)[0] = bad
    with pytest.raises(SimulationDivergedError, match=f"non-finite {field}"):
        check_healthy(model, data)


def test_check_healthy_passes_finite_fields_whose_sum_overflows():
    """Finite entries whose sum is infinite (1e308 twice) are healthy: the quick sum test
    falls back to the field by field check."""
    model = load("disc")
    data = mujoco.MjData(model)
    data.qvel[:2] = 1e308
    with np.errstate(over="ignore"):
        assert not np.isfinite(data.qvel.sum())
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the quick test warns of nothing
        check_healthy(model, data)


@pytest.mark.parametrize("kwargs, match", [
    ({"duration": -1.0}, "duration = -1.0"),
    ({"duration": 1.0, "record_every": 0}, "record_every = 0"),
    ({"duration": 1.0, "control": lambda t: np.zeros(5)}, r"shape \(5,\); expected \(2,\)"),
])
def test_rollout_bad_input(kwargs, match):
    model = load("disc")
    with pytest.raises(ValueError, match=match):
        rollout(model, mujoco.MjData(model), **kwargs)
