"""simulate / predict / compare, and the README's example that uses them."""

import math
import re
from pathlib import Path

import numpy as np
import pytest

import wmr_mujoco as wmr
import wmr_mujoco.api

README = Path(__file__).resolve().parents[1] / "README.md"


def test_readme_example_runs_and_physics_follows_the_model():
    """The README's omni3 example, executed as printed.

    The judged requirement for omni3 is a worst position error of at most 1 % of the
    path over the run (``robots/requirements.py``); ``run.passed`` checks it and every
    other judged metric.
    """
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(), flags=re.DOTALL)
    example = next(b for b in blocks if "wmr.compare(" in b)
    scope: dict[str, object] = {}
    exec(compile(example, str(README), "exec"), scope)
    run = scope["run"]
    assert run.passed
    path = float(np.sum(np.linalg.norm(np.diff(run.model.pose[:, :2], axis=0), axis=1)))
    gap = np.linalg.norm(run.sim.pose[:, :2] - run.model.pose[:, :2], axis=1)
    assert gap.max() <= 0.01 * path  # the 1 % of path requirement, over the whole run
    # Full rate: one state per physics step over 3 s, the start included.
    dt = wmr.load("omni3").opt.timestep
    assert run.sim.states.shape == (round(3.0 / dt) + 1, 3)
    assert run.sim.time[1] == pytest.approx(dt)
    np.testing.assert_allclose(wmr.predict("omni3", scope["twist"], duration=3.0).states,
                               run.model.states)


def test_predict_is_the_closed_form_of_a_constant_twist():
    """For a constant body twist (u, v, r) the pose is a circular arc (independent check):
    ψ(t) = ψ0 + r t, and the world velocity rotates with ψ, so
    x(t) = x0 + (u (sin ψ − sin ψ0) + v (cos ψ − cos ψ0)) / r, and likewise y."""
    u, v, r = 0.2, 0.1, 0.5
    model = wmr.predict("omni3", [u, v, r], 2.0)
    x0, y0, psi0 = model.pose[0]
    psi = psi0 + r * model.time
    x = x0 + (u * (np.sin(psi) - np.sin(psi0)) + v * (np.cos(psi) - np.cos(psi0))) / r
    y = y0 + (-u * (np.cos(psi) - np.cos(psi0)) + v * (np.sin(psi) - np.sin(psi0))) / r
    # RK4 at 4 ms: local error O(Δt⁵) per step, far below 1 µm over 500 steps.
    np.testing.assert_allclose(model["x"], x, atol=1e-6)
    np.testing.assert_allclose(model["y"], y, atol=1e-6)
    np.testing.assert_allclose(model["heading"], psi, atol=1e-9)


@pytest.mark.parametrize("call, match", [
    (lambda: wmr.simulate("omni3", [0.1, "fast", 0.0], 1.0),
     r"inputs\[1\] = 'fast'; give a finite number or a function of time"),
    (lambda: wmr.simulate("omni3", [0.1, math.nan, 0.0], 1.0), r"inputs\[1\] = nan"),
    (lambda: wmr.simulate("omni3", "fast", 1.0), r"inputs = 'fast'"),
    (lambda: wmr.predict("omni3", [0.1, 0.0, 0.0], -1.0),
     r"duration = -1.0; must be a finite real number of seconds in \(0, inf\)"),
    (lambda: wmr.predict("omni3", [0.1, 0.0, 0.0], None), r"duration = None; must be a finite"),
    (lambda: wmr.predict("omni3", [0.1, 0.0, 0.0], [1.0]), r"duration = \[1.0\]; must be"),
    (lambda: wmr.predict("omni3", [0.1, 0.0, 0.0], "1.0"), r"duration = '1.0'; must be"),
    (lambda: wmr.predict("omni3", [0.1, 0.0, 0.0], math.inf), r"duration = inf; must be"),
    (lambda: wmr.predict("omni3", [0.1, 0.0, 0.0], 1.0, settle=-0.1),
     r"settle = -0.1; must be a finite real number of seconds in \[0, inf\)"),
    (lambda: wmr.predict("omni3", [0.1, 0.0, 0.0], 1.0, settle="0.5"), r"settle = '0.5'"),
    (lambda: wmr.simulate("omni3", [0.1, 0.0], 1.0),
     r"2 inputs; robot 'omni3' takes 3 input channels for kinematic scenarios"),
    (lambda: wmr.compare("disc", [0.1, 0.0, 0.0], 1.0, kind="dynamic"),
     r"3 inputs; robot 'disc' takes 2 input channels for dynamic scenarios"),
    (lambda: wmr.compare("segway", [0.1], 1.0), r"unknown robot 'segway'"),
    (lambda: wmr.simulate("omni3", [0.1, 0.0, 0.0], 1.0, kind="flying"), "flying"),
])
def test_bad_arguments_are_value_errors(call, match, monkeypatch):
    """Refused before any work: MuJoCo is never stepped."""
    import mujoco

    def stepped(*args):
        raise AssertionError("simulated before the arguments were checked")

    monkeypatch.setattr(mujoco, "mj_step", stepped)
    with pytest.raises(ValueError, match=match):
        call()


def test_an_unknown_metric_is_a_value_error_listing_the_valid_ones():
    from wmr_mujoco.api import Comparison
    from wmr_mujoco.validation.metrics import Row

    rows = [Row("disc", "s", "worst position error", 0.1, "m"),
            Row("disc", "s", "worst heading error", 0.2, "°")]
    comparison = Comparison(None, None, rows)  # type: ignore[arg-type]
    assert comparison.metric("worst heading error") == 0.2
    with pytest.raises(ValueError, match=r"metric 'slip' not found; valid metrics: "
                       r"worst heading error \[°\], worst position error \[m\]"):
        comparison.metric("slip")
    with pytest.raises(ValueError, match=r"metric 'worst heading error' \[rad\] not found"):
        comparison.metric("worst heading error", "rad")


def test_trajectory_names_its_components():
    model = wmr.predict("disc", [0.5, 0.0], 0.5)
    with pytest.raises(KeyError, match="the components are x, y, heading"):
        model["speed"]


def test_dir_lists_the_public_names_for_completion():
    import wmr_mujoco

    shown = dir(wmr_mujoco)
    assert {"simulate", "predict", "compare", "load", "Trajectory"} <= set(shown)
    assert "importlib" not in shown and "Any" not in shown
def _never_stepped(monkeypatch):
    import mujoco

    def stepped(*args):
        raise AssertionError("simulated before the arguments were checked")

    monkeypatch.setattr(mujoco, "mj_step", stepped)


def test_a_run_too_long_for_memory_is_refused_first_naming_the_cap(monkeypatch):
    """``simulate("omni3", u, 1e9)``: about 1e12 steps of omni3's step, far over any
    memory; refused before anything is stepped, with the cap and how to raise it."""
    dt = wmr.load("omni3").opt.timestep
    _never_stepped(monkeypatch)
    monkeypatch.delenv("WMR_MAX_MEMORY", raising=False)
    steps = re.escape(f"{1e9 / dt:.3g}")
    for call in (wmr.simulate, wmr.predict, wmr.compare):
        with pytest.raises(ValueError, match=rf"duration = 1e\+09 s is {steps} steps of "
                           rf"{re.escape(f'{dt:g}')} s: .* over the memory cap of 2 GiB .* "
                           r"max_memory=BYTES or the environment variable WMR_MAX_MEMORY"):
            call("omni3", [0.2, 0, 0], 1e9)


def test_the_memory_cap_is_raised_or_lowered_by_argument_or_environment(monkeypatch):
    # 0.1 s of disc is 40 steps of its 2.5 ms; each keeps at least its 12-number physics
    # state twice (192 bytes): 1 KiB is far too little, 10 MiB is plenty.
    with pytest.raises(ValueError, match=r"over the memory cap of 1000 B"):
        wmr.predict("disc", [0.1, 0.0], 0.1, max_memory=1000)
    monkeypatch.setenv("WMR_MAX_MEMORY", "1K")
    with pytest.raises(ValueError, match=r"over the memory cap of 1 KiB"):
        wmr.predict("disc", [0.1, 0.0], 0.1)
    steps = round(0.1 / wmr.load("disc").opt.timestep)
    assert len(wmr.predict("disc", [0.1, 0.0], 0.1, max_memory=10 * 2**20).time) == steps + 1
    monkeypatch.setenv("WMR_MAX_MEMORY", "lots")
    with pytest.raises(ValueError, match=r"WMR_MAX_MEMORY = 'lots'; give a number of bytes"):
        wmr.predict("disc", [0.1, 0.0], 0.1)


def test_a_duration_under_one_timestep_is_named(monkeypatch):
    dt = re.escape(f"{wmr.load('omni3').opt.timestep:g}")
    _never_stepped(monkeypatch)
    with pytest.raises(ValueError, match=rf"duration = 1e-09 s is shorter than one timestep "
                                         rf"of omni3 \({dt} s\); give at least {dt} s"):
        wmr.compare("omni3", [0.2, 0, 0], 1e-9)


def test_world_frame_for_a_robot_without_world_rates_is_an_error(monkeypatch):
    _never_stepped(monkeypatch)
    with pytest.raises(ValueError, match=r"world_frame=True: diffdrive's kinematic inputs are "
                                         r"its own rates, never world rates; robots whose "
                                         r"inputs can be world rates: omni3"):
        wmr.simulate("diffdrive", [0.2, 0.0], 1.0, world_frame=True)


def test_inputs_beyond_the_actuators_limits_warn_once_naming_them():
    """u = 5 m/s along x: omni3's wheels sit at 0°, 120° and 240° around the centre, each
    rolling tangentially, so wheels 2 and 3 turn at |sin 120°| u / R = 0.866 · 5 / 0.05 =
    86.6 rad/s; their servo's ctrlrange is ±60 rad/s (``wmr info omni3``), wheel 1 at 0."""
    with pytest.warns(wmr.api.InputClippedWarning) as caught:
        wmr.simulate("omni3", [5.0, 0.0, 0.0], 0.01, settle=0.0)
    assert len(caught) == 1
    text = str(caught[0].message)
    assert "actuator 'wheel2' asked for -86.6 (inputs (5, 0, 0) at t = 0 s), beyond its " \
           "ctrlrange [-60, 60]" in text
    assert "'wheel3' asked for 86.6" in text and "'wheel1'" not in text


def test_inputs_within_the_limits_do_not_warn(recwarn):
    wmr.simulate("omni3", [0.2, 0.0, 0.0], 0.01, settle=0.0)
    assert not [w for w in recwarn if issubclass(w.category, wmr.api.InputClippedWarning)]


def test_an_input_function_that_raises_is_named_with_its_channel_and_time(monkeypatch):
    with pytest.raises(ValueError, match=r"inputs\[1\] raised ZeroDivisionError: float "
                                         r"division by zero at t = 0.2 s"):
        wmr.predict("omni3", [0.2, lambda t: 1.0 / (t - 0.2), 0.0], 0.5)
    _never_stepped(monkeypatch)  # one that fails at once fails before any work
    with pytest.raises(ValueError, match=r"inputs\[2\]\(0\) returned 'x'; an input function "
                                         r"must return a finite real number"):
        wmr.simulate("omni3", [0.2, 0.0, lambda t: "x"], 0.5)


def test_a_numpy_array_of_constants_is_an_input():
    np.testing.assert_array_equal(
        wmr.predict("omni3", np.array([0.2, 0.0, 0.1]), 0.2).inputs,
        wmr.predict("omni3", [0.2, 0.0, 0.1], 0.2).inputs)
    assert wmr.predict("omni3", [np.float32(0.2), np.int64(0), 0.1], 0.2).inputs[0, 0] == (
        pytest.approx(0.2))


def test_a_robot_name_in_any_case_is_the_robot():
    assert wmr.predict("OMNI3", [0.2, 0.0, 0.0], 0.1).state_names == ("x", "y", "heading")


def test_a_settle_longer_than_the_cap_allows_is_refused_first(monkeypatch):
    _never_stepped(monkeypatch)
    monkeypatch.delenv("WMR_MAX_MEMORY", raising=False)
    with pytest.raises(ValueError, match=r"settle = 1e\+09 s is longer than the longest run "
                                         r"the memory cap allows"):
        wmr.predict("disc", [0.1, 0.0], 1.0, settle=1e9)
