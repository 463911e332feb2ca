"""The roller study's peer measurement names a missing peer and how to point at it."""

import pytest

from wmr_mujoco.bench.omni_study import measure_peer, study_configs, table
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.peer import Summary


def test_missing_peer_names_the_path_and_the_variable(tmp_path):
    with pytest.raises(FileNotFoundError, match=r"scene\.xml \(install mujoco-menagerie, "
                                                  r"or set WMR_PEER_SCENE"):
        measure_peer(None, tmp_path / "scene.xml")


def test_design_study_runs_at_the_robots_default_simulation():
    """Every roller design is built at omni3's own contact time constant and step (the
    study varies the rollers only), and the default design's row is the shipped model."""
    configs = dict(study_configs())
    assert all(p.sim == OmniParams().sim for p in configs.values())
    default = OmniParams()
    assert configs[f"{default.roller_shape}, 2×{default.rollers_per_row}"] == default


def test_a_diverged_row_prints_no_run_figures():
    # A diverged configuration (measure_or_diverged) keeps its ripple; its run figures
    # are NaN and print as n/a, the real-time factor without a "×".
    nan = float("nan")
    row = table([Summary("barrel, 2×6: diverged", 0.016, nan, nan, nan, nan, nan)])
    assert row.splitlines()[-1] == "| barrel, 2×6: diverged | 0.016 | n/a | n/a | n/a | n/a | n/a |"
