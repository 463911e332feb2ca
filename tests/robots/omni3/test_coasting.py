"""omni3 coasting: the figures' definitions on known motions, and the judged run."""

import numpy as np
import pytest

from wmr_mujoco.robots import omni3
from wmr_mujoco.robots.omni3 import coasting as co


def test_slope_and_velocity_direction_on_known_motions():
    """A line's slope is exact; a platform at body twist (u, 0, r) turns its velocity at
    r (χ = ψ), one moving sideways (0, v, 0) at heading ψ has χ = ψ + 90°."""
    t = np.linspace(0.0, 2.0, 51)
    assert co.slope(t, 3.0 - 0.5 * t) == pytest.approx(-0.5)
    psi = 0.7 * t
    pose = np.column_stack([0 * t, 0 * t, psi])
    chi = co.velocity_direction(pose, np.column_stack([0.3 + 0 * t, 0 * t, 0.7 + 0 * t]))
    np.testing.assert_allclose(chi, psi, atol=1e-12)
    side = co.velocity_direction(pose, np.column_stack([0 * t, 0.2 + 0 * t, 0 * t]))
    np.testing.assert_allclose(side, psi + np.pi / 2, atol=1e-12)


def test_coast_figures_declared():
    """The three coasting figures carry issue 16's 5 % (open over the family), and the physics does
    lose energy and yaw rate (relative figures of a coast that lost nothing would be
    vacuous): 0.005 W over the 3 s coast is over a tenth of the translational energy
    ½ M u² alone (M = 2.54 kg, u = 0.3 m/s: 0.11 J). Whether they are met is the family's
    verdict (``python -m wmr_mujoco.bench.omni_families``), not one draw's."""
    res = co.evaluate_coast(omni3.SPEC.scenario(co.COAST_SPEC.name), None)
    m = {x.name: x for x in res.metrics}
    assert m["energy lost per second, physics"].value > 0.005
    assert m["yaw-rate decay, physics"].value > 0
    for name in ("yaw-rate decay", "energy lost per second", "velocity-direction turn rate"):
        assert m[f"{name}: hybrid vs physics"].target is co.COAST
    assert not co.COAST.judged  # open over the family (issue 24)


def test_slow_coast_keeps_its_yaw_rate():
    """Issue 24: after (0.20, 0, 1) a wheel's rate passes through zero at a hand-over; the
    overlap friction timed by Δφ/|θ̇| stopped the model's yaw (0.01 rad/s at 2.75 s against
    the physics' 1.0). Timed by the crossing time it stays above half the physics' yaw rate
    throughout (the collapse took it to 1 %)."""
    scenario = omni3.SPEC.scenario(co.COAST_SPEC.name).member(
        {"phase": 0.0, "speed": 0.20, "yaw_rate": 1.0, "coast": 3.0, "ramp": 0.5})
    res = co.evaluate_coast(scenario, None)
    phys, model = (s for s in res.series[:2])
    assert phys.label == "physics" and model.label == "hybrid"
    assert np.all(model.y >= 0.5 * phys.y)
