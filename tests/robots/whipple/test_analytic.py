"""The linearised Whipple bicycle against the benchmark's published numbers.

References (typed in from Meijaard et al. 2007, Table 2 and the eigenvalue table, via the
reference page): the matrices carry 14 decimals, so the entries are compared to 1e-9; the
eigenvalues are published to 4 decimals, so they are compared to 5e-5 (half the last
digit); the critical speeds to 7 decimals: 5e-8. K0 is also checked independently, as the
Hessian of the potential energy of the bicycle computed from its geometry.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from wmr_mujoco.robots.whipple import analytic as wa
from wmr_mujoco.robots.whipple.params import WhippleParams

PUBLISHED = {
    "M": [[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]],
    "C1": [[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]],
    "K0": [[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]],
    "K2": [[0.0, 76.59734589573222], [0.0, 2.65431523794604]],
}
EIGENVALUES = {
    0.0: [-5.5309, -3.1316, 3.1316, 5.5309],
    1.0: [-7.1101, -3.1342, complex(3.5270, -0.8077), complex(3.5270, 0.8077)],
    3.0: [-10.3510, -2.6337, complex(1.7068, -2.3158), complex(1.7068, 2.3158)],
    4.5: [-13.1061, -0.7250, complex(-0.2628, -3.7266), complex(-0.2628, 3.7266)],
    5.0: [-14.0784, complex(-0.7753, -4.4649), complex(-0.7753, 4.4649), -0.3229],
    6.0: [-16.0854, complex(-1.5264, -5.8767), complex(-1.5264, 5.8767), -0.0041],
    7.0: [-18.1579, complex(-2.1388, -7.1953), complex(-2.1388, 7.1953), 0.1027],
    10.0: [-24.6246, complex(-3.7202, -10.9068), complex(-3.7202, 10.9068), 0.1611],
}


@pytest.fixture(scope="module")
def mats() -> wa.WhippleMatrices:
    return wa.matrices(WhippleParams())


@pytest.mark.parametrize("name", list(PUBLISHED))
def test_matrices_match_published(mats, name):
    np.testing.assert_allclose(getattr(mats, name), PUBLISHED[name], rtol=0, atol=1e-9)


@pytest.mark.parametrize("v", list(EIGENVALUES))
def test_eigenvalues_match_published(mats, v):
    got = wa.eigenvalues(v, mats)
    ref = np.array(EIGENVALUES[v], complex)
    ref = ref[np.lexsort((ref.imag, ref.real))]
    np.testing.assert_allclose(got.real, ref.real, atol=5e-5)
    np.testing.assert_allclose(got.imag, ref.imag, atol=5e-5)


def test_critical_speeds(mats):
    assert abs(wa.weave_speed(mats) - 4.2923825) < 5e-8
    assert abs(wa.capsize_speed(mats) - 6.0242620) < 5e-8


def test_modes_named_at_5_mps(mats):
    m = wa.modes(5.0, mats)
    assert abs(m.weave - complex(-0.7753, 4.4649)) < 1e-4
    assert abs(m.capsize - (-0.3229)) < 1e-4
    assert abs(m.castering - (-14.0784)) < 1e-4


def test_no_weave_pair_at_rest(mats):
    assert math.isnan(wa.modes(0.0, mats).capsize)


# ---- independent check of K0: potential energy of the constrained geometry ----------

def _rot(axis, angle):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


def _potential(p: WhippleParams, lean: float, steer: float) -> float:
    """V / g = -Σ m z (paper frame, z down) with both wheels on the floor.

    Rear frame: lean φ about the ground line, then pitch θ about the rear axle; front
    frame: rotation δ about the head axis; θ solves "front wheel's lowest point on the
    floor". Rear contact at the origin (a knife edge rolls about it).
    """
    w, c, lam = p.wheelbase, p.trail, p.head_angle
    c_r0 = np.array([0.0, 0.0, -p.rear_radius])
    g0 = np.array([w + c, 0.0, 0.0])
    axis0 = np.array([math.sin(lam), 0.0, math.cos(lam)])
    steer_rot = _rot(axis0, steer)
    lean_rot = _rot([1, 0, 0], lean)
    c_r = lean_rot @ c_r0

    def place(pitch):
        rb = lean_rot @ _rot([0, 1, 0], pitch)
        rear_pt = lambda q: c_r + rb @ (q - c_r0)  # noqa: E731
        front_pt = lambda q: rear_pt(g0 + steer_rot @ (q - g0))  # noqa: E731
        axle = rb @ steer_rot @ np.array([0.0, 1.0, 0.0])
        return rear_pt, front_pt, axle

    def front_gap(pitch):
        _, front_pt, axle = place(pitch)
        centre = front_pt(np.array([w, 0.0, -p.front_radius]))
        return centre[2] + p.front_radius * math.sqrt(1.0 - axle[2] ** 2)

    pitch = brentq(front_gap, -0.3, 0.3, xtol=1e-15)
    rear_pt, front_pt, _ = place(pitch)
    xb, zb = p.rear_frame_com
    xh, zh = p.front_frame_com
    z = (p.rear_mass * c_r[2] + p.rear_frame_mass * rear_pt(np.array([xb, 0, zb]))[2]
         + p.front_frame_mass * front_pt(np.array([xh, 0, zh]))[2]
         + p.front_mass * front_pt(np.array([w, 0, -p.front_radius]))[2])
    return -z


def test_k0_is_hessian_of_potential_energy(mats):
    """K0 = ∂²(V/g)/∂q² at upright, h = 1e-3 rad.

    Diagonal: 4th-order central differences, truncation ~h⁴ V⁽⁶⁾/90 ≈ 1e-12 · 100 and
    round-off ≈ 1e-16 · 100 / h² = 1e-8 (measured: 5e-8). Cross term: the 2nd-order
    stencil, truncation h² (V_φφφδ + V_φδδδ)/6 ≈ 1e-6 · 10 (measured: 2.7e-6). Bound 1e-5.
    """
    p = WhippleParams()
    h = 1e-3

    def v(a, b):
        return _potential(p, a, b)

    hess = np.zeros((2, 2))
    for i in range(2):
        e = np.eye(2)[i] * h
        f = [v(*(k * e)) for k in (-2, -1, 0, 1, 2)]
        hess[i, i] = (-f[0] + 16 * f[1] - 30 * f[2] + 16 * f[3] - f[4]) / (12 * h * h)
    cross = (v(h, h) - v(h, -h) - v(-h, h) + v(-h, -h)) / (4 * h * h)
    hess[0, 1] = hess[1, 0] = cross
    np.testing.assert_allclose(hess, mats.K0, atol=1e-5)
