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


def test_coast_figures_judged_and_met():
    """The hybrid model (impacts, the weight's moment over the roller arc, the compliant
    hand-over loss and the rows' friction while two rollers touch) meets issue 16's 5 % on
    each coasting figure, judged: the yaw-rate decay, the velocity's turn rate and the
    energy lost per second. The Lagrange model would give zero for all three, so the
    physics must lose energy and its yaw rate must decay (relative figures of a coast that
    lost nothing would be vacuous); 0.005 W over the 3 s coast is over a tenth of the
    translational energy ½ M u² alone (M = 2.54 kg, u = 0.3 m/s: 0.11 J)."""
    res = co.evaluate_coast(omni3.SPEC.scenario(co.COAST_SPEC.name), None)
    m = {x.name: x for x in res.metrics}
    assert m["energy lost per second, physics"].value > 0.005
    assert m["yaw-rate decay, physics"].value > 0
    for name in ("yaw-rate decay", "energy lost per second", "velocity-direction turn rate"):
        row = m[f"{name}: hybrid vs physics"]
        assert row.target is co.COAST and row.value <= 5.0
