"""The mounted disc's wheel model and torque adapter take J from the compiled model."""

from dataclasses import replace

import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.robots import get_spec
from wmr_mujoco.robots.disc.params import DiscParams
from wmr_mujoco.robots.disc.wheel import mounted_wheel
from wmr_mujoco.validation.runner import run_scenario

ARMATURE = 0.01


@pytest.fixture(scope="module")
def geared():
    p = DiscParams()
    return replace(p, drive=replace(p.drive, wheel_armature=ARMATURE))


def test_mounted_wheel_constants(geared):
    w = mounted_wheel(load("disc", geared))
    assert w.mass == pytest.approx(geared.total_mass)
    assert w.inertia == pytest.approx(geared.wheel.axial_inertia + ARMATURE, rel=1e-12)
    assert (w.radius, w.friction) == (geared.wheel.radius, geared.sim.friction)
    assert w.normal == pytest.approx(geared.total_mass * 9.81)


def test_torque_scenario_with_armature_passes(geared):
    """wheel_armature = 0.01 gave a false 13.9 % acceleration error when J ignored it."""
    spec = get_spec("disc")
    result = run_scenario(spec, spec.scenario("torque"), params=geared)
    row = next(r for r in result.rows if r.metric == "rolling acceleration error")
    assert result.passed, [(r.metric, r.value) for r in result.rows if r.passed is False]
    # The error a J without the armature would show: (J + A + mR²)/(J + mR²) − 1.
    p = geared
    stale = ARMATURE / (p.wheel.axial_inertia + p.total_mass * p.wheel.radius**2)
    assert abs(row.value) < 100.0 * stale / 10
