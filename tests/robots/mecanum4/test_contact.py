"""The collider's contact and rolling rows, against MuJoCo's collision and closed forms."""

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.models.colliders import colliders
from wmr_mujoco.robots.mecanum4 import contact as mc
from wmr_mujoco.robots.mecanum4 import roller as mr
from wmr_mujoco.robots.mecanum4.builder import WHEELS
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels import rolling_radius_profile

P = MecanumParams()
R, B, G = P.wheel_radius, P.roller_half_width, P.roller_angle
N = P.rollers_per_wheel
ELLIPSOID = mc.RollerGeometry(R, B, G, N, mr.ellipsoid_semi_axis(R, B, G))
IDEAL = mc.RollerGeometry(R, B, G, N)
HALF = math.pi / N


def _mujoco_contact(model, wheel, angle):
    """Nearest point of the wheel's roller colliders to the floor, from the axle (MuJoCo).

    In the chassis axes (x ahead, y the axle, z up), which do not turn with the wheel.
    """
    data = mujoco.MjData(model)
    data.qpos[:] = model.qpos0
    data.qpos[2] += 0.5  # lift the free base clear of the floor
    jid = model.joint(wheel).id
    data.qpos[model.jnt_qposadr[jid]] = angle
    mujoco.mj_kinematics(model, data)
    floor = model.geom("floor").id
    best, point = np.inf, None
    for g in colliders(model):
        if (model.geom(g).name or "").startswith(f"{wheel}_roller"):
            fromto = np.zeros(6)
            dist = mujoco.mj_geomDistance(model, data, g, floor, 2.0, fromto)
            if dist < best:
                best, point = dist, fromto[:3].copy()
    return point - data.xanchor[jid]  # the chassis sits level and square: world axes


@pytest.mark.parametrize("wheel", [0, 1])
def test_ellipsoid_contact_is_mujocos_lowest_point(wheel):
    # The closed-form support point against MuJoCo's own distance query on the compiled
    # model (chassis level, wheel frame), at wheel angles over a whole pitch, for both
    # roller-angle signs (FL −γ, FR +γ). 0.1 µm: far below the ±7.6 mm walk along the
    # axle and the 0.07 mm drop of the rolling height that matter.
    model = load("mecanum4")
    name, _, _, sign = WHEELS[wheel]
    for phase in np.linspace(-0.99 * HALF, 0.99 * HALF, 7):
        q, _ = mc.contact(ELLIPSOID, float(phase), sign)
        np.testing.assert_allclose(q, _mujoco_contact(model, name, phase), atol=1e-7)


def test_ellipsoid_contact_leaves_the_ideal_line():
    # The ellipsoid osculates the ideal profile at the middle: same contact there; at the
    # hand-over it touches below the envelope, ahead of the axle and short of the ideal
    # walk d tan φ tan γ (docs/mecanum.md §3).
    q0, _ = mc.contact(ELLIPSOID, 0.0, 1.0)
    np.testing.assert_allclose(q0, [0.0, 0.0, -R], atol=1e-15)
    q, _ = mc.contact(ELLIPSOID, 0.99 * HALF, 1.0)
    ideal, _ = mc.contact(IDEAL, 0.99 * HALF, 1.0)
    assert -q[2] < R and q[0] != 0.0 and 0.0 < q[1] < ideal[1]


def test_ideal_rows_are_the_secant_law():
    # Ideal profile: h = R and u_y/u_x = tan γ / cos φ
    # (robots/roller_wheels/pitch_averaged.py), so the u and v columns of the rows are 1/R and
    # tan γ sec φ / R, and the lever column is
    # (x tan γ sec φ − y − d tan φ tan γ)/R with the walk along the axle.
    pos, signs = np.array([[0.15, 0.15], [0.15, -0.15], [-0.15, 0.15]]), np.array([-1, 1, 1])
    for phase in (-0.15, 0.05, 0.17):
        rows = mc.constraint_rows(IDEAL, pos, signs, np.full(3, phase))
        slope = signs * math.tan(G) / math.cos(phase)
        walk = signs * (R - B) * math.tan(phase) * math.tan(G)
        np.testing.assert_allclose(rows * R, np.column_stack(
            [np.ones(3), slope, pos[:, 0] * slope - pos[:, 1] - walk]), rtol=1e-12)


def test_ideal_sideways_mean_is_the_mean_cosine():
    # Sideways, every wheel at the same |φ|: the rows agree and v = v_cmd cos φ, so the
    # mean is sin φ_m / φ_m (robots/mecanum4/roller.mean_lateral_factor). The midpoint
    # rule over 128 samples is exact to ~φ_m²/(24·128²) ≈ 1e-7.
    pos = np.array([[0.15, 0.15], [0.15, -0.15], [-0.15, 0.15], [-0.15, -0.15]])
    signs = np.array([-1.0, 1.0, 1.0, -1.0])
    rates = np.array([-1.0, 1.0, 1.0, -1.0]) * 0.3 / R  # H(γ) (0, 0.3, 0)
    nu = mc.mean_twist(IDEAL, pos, signs, rates)
    assert nu[1] / 0.3 == pytest.approx(mr.mean_lateral_factor(HALF), rel=1e-6)
    assert abs(nu[0]) < 1e-12 and abs(nu[2]) < 1e-12


@pytest.mark.parametrize(("twist", "weight"), [((0.3, 0.0, 0.0), "h"),
                                               ((0.0, 0.3, 0.0), "h cos φ")])
def test_collider_translation_mean_follows_mujocos_rolling_radius(twist, weight):
    # Independent route: MuJoCo's rolling radius h(θ) of wheel FL over a revolution
    # (robots.roller_wheels.rolling_radius_profile, mj_geomDistance). Ahead every
    # wheel rolls on h, u = u_cmd ⟨h⟩/R; sideways the rows agree at equal |φ| and
    # v = v_cmd h cos φ / R (γ = 45°). The profile's even grid (Δ = 0.25°) averages a
    # function with a kink at each hand-over (the slope of h cos φ flips by ≈ 2 sin φ_m):
    # error ≈ Δ²/12 · 2 sin φ_m / (2π/n) ≈ 2e-6; the effect tested (⟨h⟩ below R) is 3e-4.
    model = load("mecanum4")
    angle = np.linspace(0.0, 2.0 * np.pi, 1441)[:-1]
    h = rolling_radius_profile(model, "wheel_fl", "wheel_fl_roller", samples=1441)[:-1]
    factor = h / R if weight == "h" else h * np.cos(mc.roller_phase(ELLIPSOID, angle)) / R
    pos = np.array([[0.15, 0.15], [0.15, -0.15], [-0.15, 0.15], [-0.15, -0.15]])
    signs = np.array([-1.0, 1.0, 1.0, -1.0])
    u, v, _ = twist
    rates = (u + v * signs) / R
    nu = mc.mean_twist(ELLIPSOID, pos, signs, rates)
    k = 0 if u else 1
    assert nu[k] / twist[k] == pytest.approx(float(np.mean(factor)), rel=5e-6)
    assert 1.0 - float(np.mean(h)) / R > 1e-4


def test_bad_geometry_and_rates_are_refused():
    with pytest.raises(ValueError, match="half_width"):
        mc.RollerGeometry(0.05, 0.06, G, N)
    with pytest.raises(ValueError, match="semi_axis"):
        mc.RollerGeometry(R, B, G, N, semi_axis=0.5 * B)
    with pytest.raises(ValueError, match="rollers"):
        mc.RollerGeometry(R, B, G, 1)
    with pytest.raises(ValueError, match="no wheel turns"):
        mc.mean_twist(IDEAL, np.zeros((4, 2)), np.ones(4), np.zeros(4))


def _mean_twist_one_by_one(geometry, pos, signs, rates, samples=128):
    """The definition, sample by sample: slip_rows and lstsq at each midpoint time."""
    turning = np.abs(rates[np.abs(rates) > 1e-12])
    period = geometry.pitch / float(np.min(turning))
    count = int(samples * math.ceil(float(np.max(turning) / np.min(turning))))
    twists = [np.linalg.lstsq(*_system(geometry, pos, signs, rates, t), rcond=None)[0]
              for t in (np.arange(count) + 0.5) * period / count]
    return np.mean(twists, axis=0)


def _system(geometry, pos, signs, rates, t):
    g, rim = mc.slip_rows(geometry, pos, signs, rates * t)
    return g, rim * rates


@pytest.mark.parametrize("geometry", [IDEAL, ELLIPSOID])
@pytest.mark.parametrize("twist", [(0.3, 0.0, 0.0), (0.3, 0.2, 0.1), (0.01, 0.3, 0.05)])
def test_mean_twist_in_chunks_is_the_sample_by_sample_mean(monkeypatch, geometry, twist):
    # The vectorised samples (slip_rows_at, pinv per sample) against slip_rows and lstsq
    # one sample at a time: the same least squares of a full-rank 4x3 system, so they
    # agree to round-off. Bound: each sampled twist to ~10 eps |ν| (4x3 SVD against QR),
    # averaged: 1e-13 absolute on twists of 0.3 m/s. CHUNK 50 makes the ~1.3k samples
    # of the 1 : 10 rate ratio run in many chunks (the chunk bookkeeping tested).
    monkeypatch.setattr(mc, "CHUNK", 50)
    pos = np.array([[0.15, 0.15], [0.15, -0.15], [-0.15, 0.15], [-0.15, -0.15]])
    signs = np.array([-1.0, 1.0, 1.0, -1.0])
    u, v, r = twist
    rates = (u + v * signs - r * 0.3 * signs * signs) / R
    np.testing.assert_allclose(mc.mean_twist(geometry, pos, signs, rates),
                               _mean_twist_one_by_one(geometry, pos, signs, rates),
                               rtol=0, atol=1e-13)
