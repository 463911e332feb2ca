"""Lynch & Park's formula for the mecanum layout against an independent contact derivation."""

import math

import numpy as np

from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok

R, A, W = 0.05, 0.15, 0.12


def _rates_from_contacts(nu: np.ndarray) -> np.ndarray:
    """θ̇_i from the no-slip condition along each contact roller's axis.

    Contact at (x, y) moves at v = (u − r y, v + r x); the wheel's rim moves it back by
    R θ̇ along x; the roller absorbs any velocity perpendicular to its axis e = (cos γ, sin γ)
    but none along it: (v − R θ̇ x̂)·e = 0, so θ̇ = v·e / (R cos γ).
    """
    pos = [(A, W, -1), (A, -W, 1), (-A, W, 1), (-A, -W, -1)]  # FL FR RL RR, sign of γ
    u, v, r = nu
    out = []
    for x, y, sg in pos:
        e = np.array([math.cos(sg * math.pi / 4), math.sin(sg * math.pi / 4)])
        out.append(np.array([u - r * y, v + r * x]) @ e / (R * e[0]))
    return np.array(out)


def test_jacobian_matches_the_contact_derivation():
    H = ok.wheel_jacobian(ok.mecanum_layout(R, A, W))
    for nu in np.random.default_rng(0).normal(size=(20, 3)):
        np.testing.assert_allclose(H @ nu, _rates_from_contacts(nu), rtol=1e-12, atol=1e-12)


def test_jacobian_written_out():
    # θ̇ = (1/R) [[1, −1, −(a+w)], [1, 1, a+w], [1, 1, −(a+w)], [1, −1, a+w]] ν
    k = A + W
    expected = np.array([[1, -1, -k], [1, 1, k], [1, 1, -k], [1, -1, k]]) / R
    np.testing.assert_allclose(ok.wheel_jacobian(ok.mecanum_layout(R, A, W)), expected,
                               atol=1e-12)


def test_consistent_wheel_rates_give_the_twist_back():
    lay = ok.mecanum_layout(R, A, W)
    nu = np.array([0.2, -0.1, 0.5])
    np.testing.assert_allclose(ok.body_twist(lay, ok.wheel_rates(lay, nu)), nu, atol=1e-12)
