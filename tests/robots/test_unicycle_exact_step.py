"""The unicycle robots' exact step under a held input: the RK4 of their rhs, to round-off."""

import numpy as np
import pytest

from wmr_mujoco.analytic.integrate import rk4_step
from wmr_mujoco.robots.diffdrive import DiffDriveKinematics
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams
from wmr_mujoco.robots.disc import DiscKinematics
from wmr_mujoco.robots.disc.params import DiscParams


@pytest.mark.parametrize("adapter", [DiscKinematics(DiscParams()),
                                     DiffDriveKinematics(DiffDriveParams())])
@pytest.mark.parametrize("u", [(0.5, 1.5), (0.3, -3.0), (-0.4, 1e-9), (0.0, 2.0)])
def test_exact_step_is_what_rk4_on_the_rhs_approximates(adapter, u):
    # 1000 held steps of 2 ms (the validation's timestep). RK4 integrates cos φ(t) with
    # Simpson's rule each step: error ≤ |v| ω⁴ Δt⁵ / 2880 ≈ 1.1e-16 m per step at
    # v = 0.5, ω = 3, so 1e-13 m over the run; round-off of 1000 additions of ~1e-3 m
    # adds ~1e-16 m each: 1e-12 m bounds both. The heading is linear in t: exact in both.
    x = y = np.array([0.1, -0.2, 0.7])
    u = np.array(u)
    for _ in range(1000):
        x = rk4_step(adapter.rhs, x, u, 0.002)
        y = adapter.exact_step(y, u, 0.002)
    np.testing.assert_allclose(y, x, rtol=0, atol=1e-12)
    # one long step is the same arc (the kinematic backend holds a whole control period)
    np.testing.assert_allclose(adapter.exact_step(np.array([0.1, -0.2, 0.7]), u, 2.0), y,
                               rtol=0, atol=1e-12)
