"""simulate_batch: members equal wmr.simulate exactly on rollout; clear errors before work."""

import re
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import wmr_mujoco as wmr
from wmr_mujoco.batch import simulate as batch_simulate
from wmr_mujoco.batch.trajectory import BatchTrajectory

DOC = Path(__file__).resolve().parents[2] / "docs" / "batch.md"
README = DOC.parents[1] / "README.md"
ROBOT = "diffdrive"  # two input channels (v, ω)
DURATION = 0.3


def _friction(mu: float):
    base = wmr.get_spec(ROBOT).params_type()
    return replace(base, sim=replace(base.sim, friction=mu))


def test_rollout_members_equal_simulate_exactly():
    """Every member, with constant or time-varying inputs and its own parameters, is what
    wmr.simulate gives alone: the same settle, schedule and C engine, so bit for bit."""
    inputs = [[0.5, 0.3], [lambda t: 0.4 * np.sin(3 * t), -0.6], [0.2, 0.0]]
    params = [None, _friction(0.3), _friction(0.3)]
    batch = wmr.simulate_batch(ROBOT, inputs, DURATION, params=params)
    assert isinstance(batch, BatchTrajectory) and batch.backend == "rollout"
    for i, (u, p) in enumerate(zip(inputs, params, strict=True)):
        alone = wmr.simulate(ROBOT, u, DURATION, p)
        member = batch.member(i)
        assert np.array_equal(member.states, alone.states), i
        assert np.array_equal(member.inputs, alone.inputs), i
        assert np.array_equal(member.time, alone.time)
    # Different inputs really give different motion (the test can fail on a mix-up).
    assert not np.allclose(batch.pose[0, -1], batch.pose[2, -1], atol=1e-3)


def test_array_inputs_one_row_per_member():
    batch = wmr.simulate_batch(ROBOT, np.array([[0.5, 0.0], [0.0, 1.0]]), DURATION)
    nstep = round(DURATION / wmr.load(ROBOT).opt.timestep)
    assert batch.pose.shape == (2, nstep + 1, 3) and len(batch) == 2
    assert batch.inputs.shape == (2, nstep, 2)
    np.testing.assert_array_equal(batch.inputs[1], np.tile([0.0, 1.0], (nstep, 1)))


def _sweep_examples() -> list[tuple[Path, str]]:
    """Every ```python block calling simulate_batch in docs/batch.md and the README."""
    found = []
    for path in (DOC, README):
        found += [(path, b) for b in re.findall(r"```python\n(.*?)```", path.read_text(),
                                                flags=re.DOTALL) if "simulate_batch(" in b]
    return found


def test_docs_sweep_example_runs_as_written():
    """The parameter sweep in docs/batch.md (and its copy in the README, once there),
    executed as printed; its last member is what wmr.simulate gives with that friction."""
    examples = _sweep_examples()
    assert any(path == DOC for path, _ in examples)
    for path, block in examples:
        scope: dict[str, object] = {}
        exec(compile(block, str(path), "exec"), scope)
        runs, mus = scope["runs"], scope["mus"]
        assert len(runs) == len(mus)
        alone = wmr.simulate(ROBOT, [0.6, 1.0], 1.0, scope["params"][-1])
        np.testing.assert_array_equal(runs.member(len(mus) - 1).states, alone.states)


@pytest.mark.parametrize(("inputs", "message"), [
    ("fast", "give one entry per member"),
    ([], "give one entry per member"),
    (np.zeros((2, 2, 2)), r"shape \(2, 2, 2\); give \(members, channels\)"),
    ([[0.5, 0.1], 0.3], r"inputs\[1\] = 0.3; each member's inputs are a sequence"),
    ([[0.5, 0.1], [0.5, "x"]], r"member 1: inputs\[1\] = 'x'"),
    ([[0.5, 0.1], [0.5, 0.1, 0.2]], r"member 1: .*3 inputs; robot 'diffdrive' takes 2"),
])
def test_bad_inputs_are_named_before_work(inputs, message):
    with pytest.raises(ValueError, match=message):
        wmr.simulate_batch(ROBOT, inputs, DURATION)


def test_bad_backend_lists_the_installed_ones():
    with pytest.raises(ValueError, match=r"backend = 'cuda'; installed backends: rollout"):
        wmr.simulate_batch(ROBOT, [[0.5, 0.1]], DURATION, backend="cuda")


def test_mjx_is_refused_with_its_reason_and_the_backend_to_use():
    """MJX is weighed and not offered: the error gives the measured gap and names warp."""
    with pytest.raises(ValueError, match=r"backend = 'mjx': .*12\.5 cm.*implicit.*"
                                         r"use backend='warp'.*'rollout'"):
        wmr.simulate_batch(ROBOT, [[0.5, 0.1]], DURATION, backend="mjx")


def test_options_of_another_backend_are_named():
    with pytest.raises(ValueError, match=r"backend 'rollout' has no option devices; its "
                                         r"options: nthread"):
        wmr.simulate_batch(ROBOT, [[0.5, 0.1]], DURATION, devices=["cpu"])


def test_bad_duration_and_params_count():
    with pytest.raises(ValueError, match=r"member 0: duration = -1"):
        wmr.simulate_batch(ROBOT, [[0.5, 0.1]], -1)
    with pytest.raises(ValueError, match="params has 1 entries for 2 members"):
        wmr.simulate_batch(ROBOT, [[0.5, 0.1]] * 2, DURATION, params=[None])


def test_robot_without_a_model_of_the_kind_is_refused():
    with pytest.raises(ValueError, match="member 0: no kinematic model for robot 'whipple'"):
        wmr.simulate_batch("whipple", [[1.0, 0.0]], DURATION)


def test_batch_too_large_for_memory_is_refused_before_work(monkeypatch):
    """2000 members x 1000 s of steps of ~30 doubles is ~ 0.3 TB: refused, naming the size."""
    monkeypatch.setattr(batch_simulate, "prepare", None)  # any settle would fail loudly
    steps = round(1000.0 / wmr.load(ROBOT).opt.timestep)
    with pytest.raises(ValueError, match=rf"2000 members x {steps} steps .* GiB"):
        wmr.simulate_batch(ROBOT, [[0.5, 0.1]] * 2000, 1000.0)


def test_too_many_members_are_refused_before_any_member_is_made():
    n = batch_simulate.MAX_MEMBERS + 1
    with pytest.raises(ValueError, match=f"{n} members; at most"):
        wmr.simulate_batch(ROBOT, np.zeros((n, 2)), DURATION)
    with pytest.raises(ValueError, match=f"{n} members; at most"):
        wmr.simulate_batch(ROBOT, [[0.0, 0.0]] * n, DURATION)


def test_members_of_different_structure_are_refused():
    base = wmr.get_spec("mecanum4").params_type()
    other = replace(base, rollers_per_wheel=base.rollers_per_wheel + 2)
    with pytest.raises(ValueError, match="member 1's model has sizes"):
        wmr.simulate_batch("mecanum4", [[0.1, 0.0, 0.0]] * 2, DURATION, params=[base, other])


@pytest.mark.parametrize("kwargs, match", [
    ({"settle": 1e9}, "settle"),            # would step for days: refused, not run
    ({"duration": 1e-5}, "shorter than one timestep"),
])
def test_steps_and_settle_are_checked_before_any_work(kwargs, match):
    args = {"duration": 0.1, **kwargs}
    duration = args.pop("duration")
    with pytest.raises(ValueError, match=match):
        wmr.simulate_batch("diffdrive", [[0.5, 0.0]] * 2, duration, **args)
