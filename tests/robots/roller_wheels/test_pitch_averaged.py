"""Roller-pitch-averaged kinematics: checked by quadrature and by hand-derived closed forms."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from wmr_mujoco.robots.mecanum4 import roller as mr
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels import pitch_averaged as pa

A, W, R = 0.15, 0.12, 0.05


@pytest.mark.parametrize("n", [6, 8, 16, 24])
def test_mean_secant_against_quadrature(n):
    phi = math.pi / n
    numeric = quad(lambda p: 1.0 / math.cos(p), -phi, phi)[0] / (2 * phi)
    assert pa.mean_secant(phi) == pytest.approx(numeric, rel=1e-12)


@pytest.mark.parametrize("n", [8, 16])
def test_averaged_rows_are_the_mean_of_the_instantaneous_rows(n):
    # Independent path: the instantaneous Jacobian with γ_eff(φ) = atan(tan γ / cos φ)
    # (mecanum_roller.effective_roller_angle), averaged over φ by quadrature.
    lay = ok.mecanum_layout(R, A, W)
    phi_m = math.pi / n

    def row(phi, i, j):
        g = mr.effective_roller_angle(abs(lay.roller_angles[i]), phi)
        inst = ok.WheelLayout(lay.positions, lay.drive_angles,
                              np.sign(lay.roller_angles) * g, lay.radii)
        return ok.wheel_jacobian(inst)[i, j]

    numeric = np.array([[quad(row, -phi_m, phi_m, args=(i, j))[0] / (2 * phi_m)
                         for j in range(3)] for i in range(4)])
    np.testing.assert_allclose(ok.wheel_jacobian(pa.averaged_layout(lay, n)), numeric,
                               rtol=1e-10, atol=1e-12)


def test_mecanum_closed_form_when_all_wheels_turn():
    # By hand (module docstring): u kept, v / k, r (a + w) / (a k + w), k = ⟨sec φ⟩.
    lay = ok.mecanum_layout(R, A, W)
    k = pa.mean_secant(math.pi / 16)
    expected = np.diag([1.0, 1.0 / k, (A + W) / (A * k + W)])
    np.testing.assert_allclose(pa.realised_twist_map(lay, 16), expected, atol=1e-12)


def test_sideways_shortfall_matches_the_small_angle_series():
    # 1 − 1/k = φ²/6 + O(φ⁴): the same leading term as 1 − sin φ / φ (docs/mecanum.md §3).
    phi = math.pi / 16
    short = 1.0 - 1.0 / pa.mean_secant(phi)
    assert short == pytest.approx(phi**2 / 6, rel=phi**2)


def test_a_wheel_at_rest_keeps_the_ideal_constraint():
    # Diagonal drive: FL and RR are at rest (rest phase φ₀ = 0, ideal constraint u = v),
    # FR and RL turn (u + k v = √2 V): u = v = √2 V / (1 + k).
    lay = ok.mecanum_layout(R, A, W)
    k = pa.mean_secant(math.pi / 16)
    V = 0.3
    nu = np.array([V, V, 0.0]) / math.sqrt(2)
    turning = np.abs(ok.wheel_jacobian(lay) @ nu) > 1e-12
    np.testing.assert_array_equal(turning, [False, True, True, False])
    got = pa.realised_twist_map(lay, 16, turning) @ nu
    np.testing.assert_allclose(got, [math.sqrt(2) * V / (1 + k)] * 2 + [0.0], atol=1e-12)


def test_omni_wheels_are_unchanged():
    lay = ok.symmetric_layout(0.03, 0.1)
    np.testing.assert_allclose(pa.realised_twist_map(lay, 8), np.eye(3), atol=1e-12)


@pytest.mark.parametrize(("call", "match"), [
    (lambda: pa.roller_half_pitch(1), "rollers"),
    (lambda: pa.mean_secant(2.0), "half_span"),
    (lambda: pa.averaged_layout(ok.mecanum_layout(R, A, W), 16, np.ones(3)), "turning"),
])
def test_bad_input_is_named(call, match):
    with pytest.raises(ValueError, match=match):
        call()
