"""The tricycle's free-wheel probe against the ICR relation, on states set by hand."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.robots import tricycle
from wmr_mujoco.robots.tricycle.params import TricycleParams
from wmr_mujoco.validation.metrics import Sample


def test_free_wheel_probe_measures_the_icr_error():
    """θ̇_R = θ̇_L (1 + k)/(1 − k), k = (w/2ℓ) tan φ: 1 % too fast reads as 1 %."""
    p = TricycleParams()
    model = load("tricycle")
    scenario = tricycle.SPEC.scenario("figure eight")
    adapter = tricycle.kinematic_adapter(scenario, model, p)
    probe = tricycle.free_wheel_probe(scenario, model, adapter, tricycle.TARGETS)
    data = mujoco.MjData(model)
    phi, left = 0.3, 5.0
    k = p.track / (2 * p.wheelbase) * np.tan(phi)
    data.joint("steer").qpos[0] = phi
    data.joint("rear_left_wheel").qvel[0] = left
    data.joint("rear_right_wheel").qvel[0] = 1.01 * left * (1 + k) / (1 - k)
    for step, t in enumerate((0.5, 1.5, 2.0)):  # the first is before the 1 s settle-in
        probe.observe(Sample(step, t, model, data, np.zeros(2), np.zeros(2), np.zeros(4)))
    (metric,) = probe.metrics()
    assert metric.value == pytest.approx(1.0, rel=1e-9) and len(probe.errors) == 2
