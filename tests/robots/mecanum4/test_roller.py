"""The ideal mecanum roller against independent geometry: it touches the wheel's cylinder."""

import math

import numpy as np
import pytest

from wmr_mujoco.robots.mecanum4 import roller as mr

R, B = 0.05, 0.005
D = R - B
G = math.pi / 4


def _surface_points(phi: float, t_max: float, gamma: float = G) -> np.ndarray:
    """Points of the ideal roller (bottom roller turned by φ with the wheel), wheel frame."""
    t = np.linspace(-t_max, t_max, 1201)
    sigma, rho = mr.ideal_profile(R, B, gamma, t)
    c, s = math.cos(gamma), math.sin(gamma)
    u = np.array([c, s, 0.0])
    e1, e2 = np.array([0.0, 0.0, 1.0]), np.cross(u, [0.0, 0.0, 1.0])
    psi = np.linspace(0.0, 2 * math.pi, 721)
    pts = (np.array([0.0, 0.0, -D])[None, None, :] + sigma[:, None, None] * u
           + rho[:, None, None] * (np.cos(psi)[None, :, None] * e1
                                   + np.sin(psi)[None, :, None] * e2))
    cp, sp = math.cos(phi), math.sin(phi)
    rot = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])  # about the axle y
    return pts.reshape(-1, 3) @ rot.T


@pytest.mark.parametrize("phi", [-0.19, 0.0, 0.11])
def test_lowest_point_is_at_the_envelope_radius(phi):
    # Zero ripple: turned by φ, the roller's lowest point is R below the axle and no point
    # leaves the cylinder. Grid error ≤ ρ(1 − cos(Δψ/2)) + κ Δσ²/8 < 1e-7 m; tolerance 1e-6 m.
    t_max = float(mr.axis_parameter(R, B, G, 0.2))
    pts = _surface_points(phi, t_max)
    assert pts[:, 2].min() == pytest.approx(-R, abs=1e-6)
    assert np.hypot(pts[:, 0], pts[:, 2]).max() <= R + 1e-9


def test_omni_limit_is_the_barrel():
    # γ = 0: the envelope of spheres is the torus section ρ = √(R² − σ²) − d (omni3's barrel).
    sigma, rho = mr.ideal_profile(R, B, 0.0, np.linspace(-0.02, 0.02, 41))
    np.testing.assert_allclose(rho, np.sqrt(R**2 - sigma**2) - D, atol=1e-12)


def test_middle_curvature_matches_the_profile_and_the_ellipsoid():
    # Finite difference of the meridian ρ(σ) at the middle (O(h²) error, h = 1e-4 m).
    h = 1e-4
    sig, rho = mr.ideal_profile(R, B, G, np.array([-h, 0.0, h]))
    kappa_fd = -np.polyfit(sig, rho, 2)[0] * 2
    assert kappa_fd == pytest.approx(1.0 / (2 * R - B), rel=1e-4)
    assert mr.middle_curvature(R, B, G) == pytest.approx(1.0 / (2 * R - B), rel=1e-12)
    a = mr.ellipsoid_semi_axis(R, B, G)
    assert B / a**2 == pytest.approx(1.0 / (2 * R - B), rel=1e-12)  # ellipse b/A² at the end


@pytest.mark.parametrize("phi", [0.0, 0.1, 0.2])
def test_effective_roller_angle_from_the_spin_velocity(phi):
    # Independent: the tilted roller spins about u' = Rot_y(φ) u; at the lowest point Q,
    # directly below the sphere centre, its surface velocity u' × (Q − P) is the free
    # direction; the constrained direction is horizontal and perpendicular to it.
    c, s = math.cos(G), math.sin(G)
    u = np.array([c * math.cos(phi), s, -c * math.sin(phi)])
    free = np.cross(u, [0.0, 0.0, -1.0])
    g_eff = float(mr.effective_roller_angle(G, phi))
    assert free[:2] @ np.array([math.cos(g_eff), math.sin(g_eff)]) == pytest.approx(0.0,
                                                                                   abs=1e-12)


def test_mean_lateral_factor_is_the_mean_of_cos():
    # Trapezoid rule, error ≤ φ_m³ h² / 6 ~ 1e-13.
    phi = np.linspace(-math.pi / 16, math.pi / 16, 10001)
    mean = np.trapezoid(np.cos(phi), phi) / (2 * math.pi / 16)
    assert mr.mean_lateral_factor(math.pi / 16) == pytest.approx(mean, rel=1e-9)


@pytest.mark.parametrize(("args", "match"), [((0.05, 0.06, G), "half_width"),
                                             ((0.05, 0.005, 1.6), "roller_angle"),
                                             ((-1.0, 0.005, G), "radius")])
def test_bad_input_is_named(args, match):
    with pytest.raises(ValueError, match=match):
        mr.middle_curvature(*args)
