"""Free and mounted disc in MuJoCo against the classic solutions, at the default settings.

Tolerances are the issue-13 requirements, stated in each metric's target.
"""

import math
from dataclasses import replace

import mujoco
import numpy as np
import pytest

from wmr_mujoco import disc_dynamics as dd
from wmr_mujoco.loading import load
from wmr_mujoco.params import DiscParams


@pytest.fixture(scope="module")
def free():
    return load("disc_free")


@pytest.fixture(scope="module")
def mounted():
    return load("disc")


def assert_passed(result):
    bad = [m.row() for m in result.metrics if not m.passed]
    assert not bad, bad


def test_disc_constants_come_from_the_model(free):
    d = dd.disc_from_model(free)
    p = DiscParams().wheel
    assert (d.radius, d.mass) == (p.radius, p.mass)
    assert d.axial_inertia == pytest.approx(p.axial_inertia)
    assert d.diametral_inertia == pytest.approx(p.diametral_inertia)


def test_set_free_state_puts_the_analytic_state_into_mujoco(free):
    disc = dd.disc_from_model(free)
    state = disc.steady_motion(0.3, 0.6).state
    data = mujoco.MjData(free)
    dd.set_free_state(free, data, disc, state)
    pose = dd.free_pose(free, data, disc.radius)
    assert pose[:2] == pytest.approx([0, 0], abs=1e-3)  # rim offset b²/a ≈ 0.03 mm
    assert pose[3] == pytest.approx(0.3, abs=1e-12)
    assert pose[4:7] == pytest.approx(state[5:8], abs=1e-12)
    mujoco.mj_step(free, data, nstep=2)
    assert data.ncon == 1  # placed at zero gap: one point contact once it settles


@pytest.mark.parametrize("scenario", [dd.incline, dd.stability_sweep, dd.steady_precession,
                                      dd.leaning_start, dd.energy_drift])
def test_free_disc_meets_the_targets(free, scenario):
    result = scenario(free)
    assert_passed(result)
    assert result.series


def test_implicitfast_misses_steady_precession(free):
    """The study's finding, kept honest: implicitfast at 2 ms is >5 % off (so the judged
    scenario can fail)."""
    m = free.__copy__()
    m.opt.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    m.opt.timestep = 0.002
    result = dd.steady_precession(m)
    assert not result.passed
    assert result.metrics[0].value > 5.0


def test_wheel_inertia_includes_the_armature():
    """J = m R²/2 + armature (0.01 gave a false 13.9 % in the torque adapter)."""
    p = DiscParams()
    p = replace(p, drive=replace(p.drive, wheel_armature=0.01))
    model = load("disc", p)
    assert dd.wheel_inertia_from_model(model, "wheel") == pytest.approx(
        0.5 * 1.5 * 0.15**2 + 0.01, rel=1e-12)
    w = dd.mounted_wheel(model)
    assert w.mass == pytest.approx(p.total_mass)


def test_slip_onset_torque(mounted):
    assert_passed(dd.slip_onset(mounted))


def test_slip_pulse_sliding_phase(mounted):
    """Pulse-phase accelerations and re-grip time within 2 %; the short coast phase is
    reported, not asserted (contact hops while sliding, see models/disc/README.md)."""
    result = dd.slip_pulse(mounted)
    got = {m.name: m for m in result.metrics}
    for name in ("sliding ẍ error", "sliding θ̈ pulse error", "re-grip time error"):
        assert got[name].passed, got[name].row()


@pytest.mark.parametrize("call, match", [
    (lambda m: dd.incline(m, slope=math.pi / 2), r"incline = 1.57.*valid range is \[0"),
    (lambda m: dd.incline(m, speed=-1.0), r"speed = -1.0 m/s .*valid range is \[0, inf\)"),
    (lambda m: dd.leaning_start(m, lean=2.0), r"lean = 2.0 rad .*valid range"),
    (lambda m: dd.energy_drift(m, speed=math.inf), r"speed = inf m/s"),
    (lambda m: dd.steady_precession(m, lean=1.6), r"lean = 1.6 rad"),
])
def test_bad_input(free, call, match):
    with pytest.raises(ValueError, match=match):
        call(free)


def test_metric_rows_are_flat_and_judged(free):
    rows = dd.metric_rows([dd.incline(free)])
    assert rows[0][0] == "incline" and rows[0][3] == "%" and rows[0][6] is True
    assert np.isfinite(rows[0][2])
