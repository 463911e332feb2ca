"""simulate / predict / compare, and the README's example that uses them."""

import math
import re
from pathlib import Path

import numpy as np
import pytest

import wmr_mujoco as wmr

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
    assert scope["gap"] <= 0.01 * path
    sim, model = scope["sim"], scope["model"]
    # Full rate: one state per physics step over 3 s, the start included.
    dt = wmr.load("omni3").opt.timestep
    assert sim.states.shape == (round(3.0 / dt) + 1, 3) and sim.time[1] == pytest.approx(dt)
    np.testing.assert_allclose(model.states, run.model.states)
    np.testing.assert_allclose(sim.states, run.sim.states)


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
