"""The differential drive's registry entry: adapter, actuator order, spin-in-place target."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.robots import diffdrive
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams
from wmr_mujoco.validation import metrics as mt
from wmr_mujoco.validation.scenarios import ScenarioKind


def test_controls_follow_the_actuator_order():
    # (v, ω) = (0, 1) turns left: the left wheel (y = +b/2) rolls at −ω b/2 and the
    # right one at +ω b/2, each divided by R for its rate servo.
    model = load("diffdrive")
    assert [model.actuator(i).name for i in range(model.nu)] == ["left_wheel", "right_wheel"]
    p = DiffDriveParams()
    adapter = diffdrive.kinematic_adapter(diffdrive.SPIN, model, None)
    ctrl = adapter.controls(np.array([0.0, 1.0]), np.zeros(3))
    assert ctrl == pytest.approx([-p.track / 2 / p.wheel.radius, p.track / 2 / p.wheel.radius])


def test_sim_state_reads_the_axle_midpoint_at_rest():
    model = load("diffdrive")
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    adapter = diffdrive.kinematic_adapter(diffdrive.SPIN, model, None)
    x = adapter.sim_state(model, data)
    assert x == pytest.approx(np.zeros(3), abs=1e-12)


def test_spin_target_is_half_a_percent_of_the_wheel_arc():
    # 1.5 rad/s reached by a 0.5 s linear ramp, held to 2 s: ∫ω dt = 1.5 (2 − 0.25) rad;
    # each wheel rolls (b/2) times that.
    b = DiffDriveParams().track
    assert diffdrive.wheel_arc(diffdrive.SPIN, b) == pytest.approx(0.5 * b * 1.5 * 1.75,
                                                                   rel=1e-3)
    target = diffdrive.TARGETS[mt.CENTRE_DRIFT_M]
    assert target.value == pytest.approx(0.005 * 0.5 * b * 1.5 * 1.75, rel=1e-3)


def test_issue_scenarios_and_the_caster_measurement_are_registered():
    names = {s.name for s in diffdrive.SCENARIOS}
    assert {"straight", "arc", "spin in place", "figure eight", "caster drag"} <= names
    assert diffdrive.SPEC.scenario("caster drag").kind is ScenarioKind.MEASUREMENT
