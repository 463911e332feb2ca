"""Worker processes (measurements and plots) give the same report as one process."""

import matplotlib.image as mpimg
import numpy as np
import pytest

from wmr_mujoco.robots import get_spec
from wmr_mujoco.sim.engine import Engine
from wmr_mujoco.validation.pool import ValidationPool
from wmr_mujoco.validation.report import write_report
from wmr_mujoco.validation.runner import run_all
from wmr_mujoco.validation.scenarios import Scenario
from wmr_mujoco.validation.signals import Piecewise, const


@pytest.fixture(scope="module")
def scenarios():
    # A kinematic run (state panels), a measurement (its own series) and a failing run
    # (nothing to plot): every branch of the figure.
    return [Scenario("disc", "short", (const(1.0, 0.5), const(0.0)), duration=1.0),
            get_spec("disc").scenario("sliding wheel"),
            Scenario("disc", "nan input", (Piecewise(((0.0, float("nan")),)), const(0.0)),
                     duration=0.1)]


def _files(folder):
    return sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*"))


def test_workers_give_the_serial_report(scenarios, tmp_path):
    serial, parallel = tmp_path / "serial", tmp_path / "parallel"
    write_report(run_all(scenarios), serial)
    with ValidationPool(parallel, workers=2) as pool:
        # The registered measurement runs in a worker; the custom scenarios here.
        assert pool.run(scenarios[:1], Engine.ROLLOUT) is None
        results = run_all(scenarios, on_result=pool.plot, offload=pool.run)
        write_report(results, parallel, pool.collect())
    assert _files(parallel) == _files(serial)
    assert "validation/disc/sliding-wheel.png" in _files(parallel)
    for name in ("validation.md", "validation.json", "summary.md"):
        assert (parallel / name).read_text() == (serial / name).read_text()
    for png in serial.rglob("*.png"):  # Agg draws the same pixels in any process
        assert np.array_equal(mpimg.imread(png), mpimg.imread(parallel / png.relative_to(serial)))


def test_interrupted_pool_leaves_nothing(scenarios, tmp_path):
    folder = tmp_path / "report"
    with pytest.raises(KeyboardInterrupt), ValidationPool(folder, workers=1) as pool:
        run_all(scenarios[:2], on_result=pool.plot, offload=pool.run)
        raise KeyboardInterrupt
    assert not folder.exists()
    with pytest.raises(ValueError, match="workers = 0"):
        ValidationPool(folder, workers=0)
