import numpy as np
import pytest

from wmr_mujoco.analytic import unicycle
from wmr_mujoco.analytic.integrate import integrate


@pytest.mark.parametrize("omega", [0.0, 0.5, -2.0])
def test_rk4_on_the_simulation_grid_matches_closed_form(omega):
    dt, n = 0.002, 5000  # 10 s
    inputs = np.tile([1.0, omega], (n, 1))
    traj = integrate(unicycle.rates, [0.1, -0.2, 0.3], inputs, dt)
    exact = unicycle.constant_input_pose([0.1, -0.2, 0.3], 1.0, omega, np.arange(n + 1) * dt)
    assert np.max(np.abs(traj - exact)) < 1e-9


def test_bad_input():
    with pytest.raises(ValueError, match="dt = 0"):
        integrate(unicycle.rates, [0, 0, 0], np.zeros((3, 2)), 0)
    with pytest.raises(ValueError, match=r"inputs must have shape \(N, N\)"):
        integrate(unicycle.rates, [0, 0, 0], np.zeros(3), 0.01)
