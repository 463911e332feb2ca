"""The steer-into-the-lean LQR on the linearised Whipple bicycle."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.linalg import solve_continuous_lyapunov

from wmr_mujoco.robots.whipple import analytic as whipple
from wmr_mujoco.robots.whipple.lean import (
    STATE_KEYS,
    BrysonWeights,
    WhippleLean,
    input_matrix,
)

SPEEDS = (2.0, 3.0)
PUSH = np.array([0.0, 0.0, 0.5, 0.0])  # the 0.5 rad/s lean-rate push


@pytest.mark.parametrize("speed", SPEEDS)
def test_unstable_uncontrolled_stable_controlled(speed):
    """Below the weave speed the open loop has an eigenvalue in the right half plane; the
    closed loop A − B K has all four in the left half plane."""
    c = WhippleLean(speed)
    assert whipple.eigenvalues(speed, whipple.matrices()).real.max() > 0.5
    assert c.closed_loop_eigenvalues().real.max() < -0.5


def test_input_matrix_is_the_steer_torque_column():
    """B is the response of ẍ to a unit steer torque: solving M q̈ = (0, 1) at rest (no
    velocity, upright) by a different route (Cramer's rule on the 2×2 M)."""
    m = whipple.matrices().M
    det = m[0, 0] * m[1, 1] - m[0, 1] * m[1, 0]
    np.testing.assert_allclose(input_matrix(whipple.matrices())[:, 0],
                               [0, 0, -m[0, 1] / det, m[0, 0] / det], rtol=1e-12)


@pytest.mark.parametrize("speed", SPEEDS)
def test_gain_is_optimal(speed):
    """LQR optimality checked independently of the Riccati solver: the cost from the push,
    J(K) = x₀ᵀ P_K x₀ with Aₖᵀ P_K + P_K Aₖ + Q + Kᵀ R K = 0 (a Lyapunov equation), is
    not lowered by any of 40 seeded 5 % perturbations of the gain."""
    c = WhippleLean(speed)
    mats = whipple.matrices()
    a, b = whipple.state_matrix(speed, mats), input_matrix(mats)
    q, r = BrysonWeights().matrices()

    def cost(k):
        ak = a - b @ k[None, :]
        if np.linalg.eigvals(ak).real.max() >= 0:
            return np.inf
        p = solve_continuous_lyapunov(ak.T, -(q + k[:, None] @ r @ k[None, :]))
        return PUSH @ p @ PUSH
    best = cost(c.gain)
    rng = np.random.default_rng(1)
    for _ in range(40):
        assert cost(c.gain * (1 + 0.05 * rng.standard_normal(4))) >= best * (1 - 1e-9)


def test_steers_into_the_lean():
    """A lean to the right (φ > 0) gets a steer torque to the right (T_δ > 0), read from the
    state's extras; at the riding speed the rear torque is 0, below it positive with the
    gain m_e r_R / τ_v (benchmark: m_e = 94 + 0.12/0.09 + 0.28/0.1225 kg, r_R = 0.3 m)."""
    c = WhippleLean(3.0)
    extra = dict(zip(STATE_KEYS, (0.05, 0.0, 0.0, 0.0), strict=True))
    cmd = c(SimpleNamespace(pose=np.zeros(3), twist=np.array([3.0, 0, 0]), extra=extra), None, 0.0)
    assert cmd[0] == 0.0 and cmd[1] > 0
    slow = c(SimpleNamespace(pose=np.zeros(3), twist=np.array([2.9, 0, 0]), extra=extra), None, 0.0)
    m_e = 94.0 + 0.12 / 0.09 + 0.28 / 0.1225
    assert slow[0] == pytest.approx(m_e * 0.3 / 0.5 * 0.1, rel=1e-9)
    with pytest.raises(ValueError, match="lean_rate"):
        c(SimpleNamespace(pose=np.zeros(3), twist=np.zeros(3), extra={"lean": 0.0}), None, 0.0)


@pytest.mark.parametrize("speed", SPEEDS)
def test_push_is_caught_on_the_linear_model(speed):
    """After the push the uncontrolled linear model's lean passes 0.5 rad within 10 s;
    with the law (torque saturation included) it stays under 0.1 rad and has decayed below
    1e-3 of its peak at 10 s (slowest closed-loop rate ≥ 3 1/s above: e^-20)."""
    mats = whipple.matrices()
    a = whipple.state_matrix(speed, mats)
    b = input_matrix(mats)[:, 0]
    c = WhippleLean(speed)
    t = np.linspace(0, 10, 1001)
    free = solve_ivp(lambda _, x: a @ x, (0, 10), PUSH, t_eval=t, rtol=1e-9, atol=1e-12)
    assert np.abs(free.y[0]).max() > 0.5
    held = solve_ivp(lambda _, x: a @ x + b * c.torque(x), (0, 10), PUSH, t_eval=t,
                     rtol=1e-9, atol=1e-12)
    lean = held.y[0]
    assert np.abs(lean).max() < 0.1
    assert abs(lean[-1]) < 1e-3 * np.abs(lean).max()


def test_the_registry_lists_the_kinds_the_law_drives():
    # The controller registry names WhippleLean's kinds without importing it (the CLI
    # stays free of MuJoCo); the two must agree.
    from wmr_mujoco.control.registry import SUPPORTS
    from wmr_mujoco.control.whipple_lean import WhippleLean

    assert SUPPORTS["whipple_lean"] == WhippleLean.kinds


@pytest.mark.parametrize("value", [-250.0, -100.0, -3.5, -0.0, 0.0, 42.0, 100.0, 1e9,
                                   float("nan")])
def test_clip_is_numpys_clip(value):
    """The law's scalar clip gives np.clip's float (the limit 100 N·m; NaN passes through)."""
    from wmr_mujoco.robots.whipple.lean import _clip

    want = float(np.clip(value, -100.0, 100.0))
    got = _clip(value, 100.0)
    assert (np.isnan(got) and np.isnan(want)) or (got == want and
                                                  np.signbit(got) == np.signbit(want))


def test_lqr_gain_is_kept_per_speed_and_handed_out_as_a_copy():
    """The kept gain is the one solved afresh (the same floats), and a caller changing its
    copy changes no later law's gain."""
    from wmr_mujoco.robots.whipple.lean import DEFAULT_PARAMS, _lqr_gain, lqr_gain

    k = lqr_gain(4.5)
    assert np.array_equal(k, _lqr_gain.__wrapped__(4.5, DEFAULT_PARAMS, BrysonWeights()))
    k[:] = 0.0
    assert np.any(lqr_gain(4.5) != 0.0)
