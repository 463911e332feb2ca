"""Plot of a dynamic omni scenario."""

import numpy as np
import pytest

from wmr_mujoco.omni_dynamic_plots import plot_scenario
from wmr_mujoco.omni_dynamic_scenarios import ScenarioResult


def test_plot_writes_a_png(tmp_path):
    t = np.linspace(0, 1, 11)
    tw = np.stack([t, 0 * t, 0.5 * t], axis=1)
    res = ScenarioResult("demo", [], {"t": t, "physics_twist": tw, "dynamic_twist": tw * 0.99,
                                      "physics_pose": tw, "dynamic_pose": tw})
    path = plot_scenario(res, tmp_path / "demo.png")
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_plot_needs_the_physics_series(tmp_path):
    with pytest.raises(ValueError, match="physics twist"):
        plot_scenario(ScenarioResult("slip", [], {"scale": np.ones(3)}), tmp_path / "x.png")
