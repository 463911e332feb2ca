"""The step-map linearisation on a case with a closed-form answer: a damped pendulum."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.sim import linearize as lin

PENDULUM = """
<mujoco>
  <option timestep="{dt}" integrator="{integrator}" gravity="0 0 -9.81"/>
  <worldbody>
    <body>
      <joint name="hinge" type="hinge" axis="0 1 0" damping="{b}"/>
      <inertial pos="0 0 -{l}" mass="{m}" diaginertia="0.01 0.01 0.01"/>
    </body>
  </worldbody>
</mujoco>
"""


def _pendulum(integrator: str, dt: float):
    m, arm, b = 2.0, 0.5, 0.8
    model = mujoco.MjModel.from_xml_string(
        PENDULUM.format(dt=dt, integrator=integrator, b=b, l=arm, m=m))
    inertia = m * arm * arm + 0.01
    # I θ̈ + b θ̇ + m g l θ = 0  →  s = −b/2I ± i sqrt(m g l / I − (b/2I)²)
    sigma = b / (2 * inertia)
    omega = math.sqrt(m * 9.81 * arm / inertia - sigma**2)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    return model, data, np.array([complex(-sigma, -omega), complex(-sigma, omega)])


def _sorted(s):
    return s[np.argsort(s.imag)]


def test_rk4_map_gives_the_closed_form():
    """RK4 at Δt = 1 ms: eigenvalue error ~(|s| Δt)⁴/120 ≈ 1e-11, FD error ~ε² = 1e-12:
    relative bound 1e-6."""
    model, data, exact = _pendulum("RK4", 1e-3)
    s = lin.continuous_eigenvalues(lin.step_map(model, data), model.opt.timestep)
    np.testing.assert_allclose(_sorted(s), exact, rtol=1e-6)


@pytest.mark.parametrize("integrator", ["implicitfast", "implicit"])
def test_first_order_map_within_its_discretisation_error(integrator):
    """Semi-implicit Euler (first order) through mjd_transitionFD: the map's eigenvalue
    error is O(s² Δt / 2); bound |s|² Δt, and it is not zero (a real discretisation)."""
    dt = 1e-3
    model, data, exact = _pendulum(integrator, dt)
    s = _sorted(lin.continuous_eigenvalues(lin.step_map(model, data), dt))
    assert np.all(np.abs(s - exact) <= np.abs(exact) ** 2 * dt)
    assert np.all(np.abs(s - exact) > 0)


def test_direct_differences_equal_transition_fd():
    """The two finite-difference routes agree on the implicit map to FD noise."""
    model, data, _ = _pendulum("implicit", 1e-3)
    a1 = lin.step_map(model, data)
    a2 = lin.step_map_direct(model, data)
    assert np.abs(a1 - a2).max() <= 1e-7 * np.abs(a1).max()


def test_bad_eps_raises():
    model, data, _ = _pendulum("RK4", 1e-3)
    with pytest.raises(ValueError, match=r"eps = 0.0; valid range is \(0, inf\)"):
        lin.step_map_direct(model, data, eps=0.0)
