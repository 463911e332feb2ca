"""The hand-over overlap's duration (crossing time) and its yaw impulse."""

import dataclasses
import math

import numpy as np
import pytest

from wmr_mujoco.robots.roller_wheels.omni_hybrid import OmniHybrid, RollerGeometry
from wmr_mujoco.robots.roller_wheels.omni_impacts import crossing_time

# omni3-like numbers, typed here (as tests/robots/roller_wheels/test_omni_hybrid.py).
B, R_WHEEL, E = 0.0075, 0.05, 0.006
GEOM = RollerGeometry(axis_distance=R_WHEEL - B, half_width=B,
                      half_length=math.sqrt(B * R_WHEEL),
                      angles=np.concatenate([2 * np.pi * np.arange(6) / 6,
                                             2 * np.pi * np.arange(6) / 6 + np.pi / 6]),
                      offsets=np.array([E] * 6 + [-E] * 6))
MODEL = OmniHybrid(mass=2.54, inertia=np.diag([0.0126, 0.0126, 0.0245]), wheel_axial=1.6e-4,
                   wheel_armature=0.004, roller_axial=1.1e-7, radius=R_WHEEL, distance=0.15,
                   rollers=GEOM)


@pytest.mark.parametrize("rate, accel", [(8.0, 0.0), (0.3, 5.0), (0.0, 3.6), (2.0, 40.0)])
def test_crossing_time_solves_the_uniformly_accelerated_turn(rate, accel):
    """t with |θ̇| t + ½ |θ̈| t² = Δφ (closed form), checked by stepping θ(t) finely: the
    first step at which the wheel has turned through the window is t to within a step."""
    window = 2.7e-4
    t = crossing_time(window, rate, accel)
    h = t / 1e5
    times = np.arange(0, 2 * t, h)
    turned = abs(rate) * times + 0.5 * abs(accel) * times ** 2
    assert times[np.argmax(turned >= window)] == pytest.approx(t, abs=2 * h)


def test_crossing_time_limits():
    # Δφ/|θ̇| without acceleration; √(2Δφ/|θ̈|) from rest; never longer than either;
    # unbounded only for a wheel at rest without acceleration.
    assert crossing_time(1e-3, -4.0, 0.0) == pytest.approx(2.5e-4, rel=1e-12)
    assert crossing_time(1e-3, 0.0, 20.0) == pytest.approx(math.sqrt(2e-3 / 20.0), rel=1e-12)
    assert crossing_time(1e-3, 4.0, 20.0) < min(2.5e-4, math.sqrt(2e-3 / 20.0))
    assert crossing_time(1e-3, 0.0, 0.0) == math.inf
    with pytest.raises(ValueError, match="window"):
        crossing_time(-1e-3, 1.0, 0.0)


def test_overlap_impulse_stays_finite_where_the_wheel_turns_back():
    """A wheel that hands over at its turning point (rate 0, the 0.20 m/s coast's wheel):
    the rows' friction acts for √(2 Δφ_w / |θ̈|), not Δφ_w/|θ̇| → ∞ (which stopped the
    platform's yaw); at speed the acceleration changes the impulse by under 1 %
    (Δφ_w / |θ̇| ≪ the time θ̈ needs to change θ̇)."""
    delta = 2.6e-6
    m = dataclasses.replace(MODEL, penetration=delta, contact_timeconst=0.002)
    th = np.full(3, np.pi + np.pi / 12 + 1e-3)
    modes = m.modes(th)
    nu = np.array([0.07, -0.16, 1.08])
    phi = float(GEOM.phases(th[0])[modes[0]])
    window = delta / abs(GEOM.contact_ahead(phi))
    at_rest = m.overlap_impulse(nu, modes, th, 0, 0.0, 3.6)
    fast = m.overlap_impulse(nu, modes, th, 0, 8.0, 0.0)
    assert at_rest == pytest.approx(fast * 8.0 * math.sqrt(2 * window / 3.6) / window,
                                    rel=1e-9)
    assert m.overlap_impulse(nu, modes, th, 0, 8.0, 3.6) == pytest.approx(fast, rel=1e-2)
    # Yaw-rate change of that impulse: far below the rate (the collapse took all of it).
    assert at_rest / m.planar_mass(modes, th)[2, 2] < 0.05 * nu[2]


def test_constraint_rows_put_the_contact_point_in_the_omega_columns():
    """Row d of wheel i reads d·(V + Ω×p) = d·V + (p×d)·Ω: its Ω columns are p × d, p the
    contact point of :meth:`contact_point`; the z-row's θ̇ entry is −x_c(φ_i). Rounding
    tolerance: a few ulps of |p| |d| ≈ 0.15 m."""
    thetas = np.array([0.1, 1.3, -2.2])
    modes = MODEL.modes(thetas)
    A = MODEL.constraint_rows(modes, thetas)
    for i, (m, th) in enumerate(zip(modes, thetas, strict=True)):
        p = MODEL.contact_point(i, m, float(th))
        for row, d in enumerate((MODEL.drive_dirs[i], np.array([0.0, 0.0, 1.0]),
                                 -MODEL.radial[i])):
            np.testing.assert_allclose(A[3 * i + row, 3:6], np.cross(p, d), rtol=0, atol=1e-15)
        phi = float(GEOM.phases(float(th))[m])
        assert A[3 * i + 1, 6 + i] == -GEOM.contact_ahead(phi)


def test_jacobian_is_kept_per_mode_and_read_only():
    """H(σ) rows (t_x, t_y, L − y_σ)/r; the same array for the same modes however typed."""
    modes = (0, 7, 3)
    H = MODEL.jacobian(modes)
    assert MODEL.jacobian(tuple(np.array(modes))) is H
    assert not H.flags.writeable
    lever = MODEL.distance - GEOM.offsets[list(modes)]
    np.testing.assert_allclose(H[:, 2], lever / R_WHEEL, rtol=1e-15)
    np.testing.assert_allclose(H[:, :2], MODEL.drive_dirs[:, :2] / R_WHEEL, rtol=1e-15)


def test_planar_mass_with_known_rows_is_the_same_matrix():
    """Passing the rows k_i already computed changes nothing (the same floats)."""
    thetas = np.array([0.4, -0.9, 2.5])
    modes = MODEL.modes(thetas)
    ks, _ = MODEL.roller_rows(modes, thetas)
    assert np.array_equal(MODEL.planar_mass(modes, thetas, ks), MODEL.planar_mass(modes, thetas))


def test_constraint_rows_shared_by_two_modes_are_the_fresh_rows():
    # An impact reads the rows of its old and its new mode at the same wheel angles; the
    # wheels that keep their roller share their rows (computed once): each mode's A must
    # be, bit for bit, what a model that never saw the other mode computes.
    thetas = np.array([0.31, -1.2, 2.05])
    old, new = (0, 3, 7), (1, 3, 7)
    shared = dataclasses.replace(MODEL)
    a_old, a_new = shared.constraint_rows(old, thetas), shared.constraint_rows(new, thetas)
    assert a_old.tobytes() == dataclasses.replace(MODEL).constraint_rows(old, thetas).tobytes()
    assert a_new.tobytes() == dataclasses.replace(MODEL).constraint_rows(new, thetas).tobytes()
    assert a_new[3:].tobytes() == a_old[3:].tobytes()  # wheels 1 and 2 kept their rollers
    assert a_new[:3].tobytes() != a_old[:3].tobytes()
