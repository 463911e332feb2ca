"""Each term of the hybrid omni model against an independent derivation."""

import dataclasses
import math

import numpy as np
import pytest

from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.omni_hybrid import (
    Drive,
    OmniHybrid,
    RollerGeometry,
    simulate,
    simulate_batch,
)

# omni3-like numbers, typed here (not read from the code under test).
B, R_WHEEL, E = 0.0075, 0.05, 0.006
GEOM = RollerGeometry(axis_distance=R_WHEEL - B, half_width=B,
                      half_length=math.sqrt(B * R_WHEEL),
                      angles=np.concatenate([2 * np.pi * np.arange(6) / 6,
                                             2 * np.pi * np.arange(6) / 6 + np.pi / 6]),
                      offsets=np.array([E] * 6 + [-E] * 6))
MODEL = OmniHybrid(mass=2.54, inertia=np.diag([0.0126, 0.0126, 0.0245]), wheel_axial=1.6e-4,
                   wheel_armature=0.004, roller_axial=1.1e-7, radius=R_WHEEL, distance=0.15,
                   rollers=GEOM)


def _lowest_point_bruteforce(phi: float) -> tuple[float, float, float]:
    """Sample the ellipsoid surface of a roller at angle φ past the bottom; return the
    lowest point's depth below the axle, its position ahead of the axle, and its distance
    from the roller axis."""
    u, v = np.meshgrid(np.linspace(-np.pi, np.pi, 721), np.linspace(0, np.pi, 721))
    # Roller frame: axis along its own z (a), cross-section radius b.
    pts = np.stack([B * np.cos(u) * np.sin(v), B * np.sin(u) * np.sin(v),
                    GEOM.half_length * np.cos(v)], axis=-1).reshape(-1, 3)
    # Wheel plane (x ahead, z up); roller centre at angle π + φ from the top.
    centre = np.array([-GEOM.axis_distance * math.sin(phi), 0.0,
                       -GEOM.axis_distance * math.cos(phi)])
    axis = np.array([-math.cos(phi), 0.0, math.sin(phi)])  # tangent
    radial = np.array([-math.sin(phi), 0.0, -math.cos(phi)])
    world = centre + pts[:, 2:3] * axis + pts[:, 0:1] * radial + pts[:, 1:2] * [0, 1, 0]
    k = int(np.argmin(world[:, 2]))
    rel = world[k] - centre
    return -world[k, 2], world[k, 0], float(np.linalg.norm(rel - (rel @ axis) * axis))


@pytest.mark.parametrize("phi", [0.0, 0.1, -0.2, 0.26])
def test_roller_contact_geometry_matches_brute_force(phi):
    """Tolerances: the 721² surface grid resolves positions to ~0.5° of the surface
    parameter, i.e. ~1e-4 m on a 0.02 m semi-axis and ~1e-7 m in depth (second order)."""
    depth, ahead, rho = _lowest_point_bruteforce(phi)
    assert GEOM.rolling_radius(phi) == pytest.approx(depth, abs=1e-6)
    assert GEOM.contact_ahead(phi) == pytest.approx(ahead, abs=2e-4)
    assert GEOM.contact_radius(phi) == pytest.approx(rho, abs=2e-4)


def test_contact_ahead_is_the_slope_of_the_rolling_radius():
    """x_c = dR/dφ (envelope theorem for a convex body rolling on a line)."""
    for phi in np.linspace(-0.4, 0.4, 9):
        slope = (GEOM.rolling_radius(phi + 1e-6) - GEOM.rolling_radius(phi - 1e-6)) / 2e-6
        assert GEOM.contact_ahead(phi) == pytest.approx(slope, abs=1e-8)


def test_lowest_roller_is_the_one_nearest_the_bottom():
    """Independent: the roller whose brute-force lowest point is deepest."""
    for theta in np.linspace(0.0, 2 * np.pi, 37):
        phis = GEOM.phases(theta)
        depths = [GEOM.rolling_radius(float(p)) if abs(p) < 1.0 else -1.0 for p in phis]
        assert GEOM.lowest(theta) == int(np.argmax(depths))
    # Rows alternate every 30°: a quarter pitch past the bottom is still the same roller.
    assert GEOM.lowest(np.pi + 0.2) == GEOM.lowest(np.pi)
    assert GEOM.lowest(np.pi + 0.3) != GEOM.lowest(np.pi)


def test_jacobian_is_lynch_park_with_the_row_lever():
    """H(σ) equals Lynch & Park's formula for wheels at (L − y_σ) ê_i (omni_kinematics)."""
    for modes in [(0, 0, 0), (6, 6, 6), (0, 7, 3)]:
        lever = 0.15 - GEOM.offsets[list(modes)]
        alpha = 2 * np.pi * np.arange(3) / 3
        layout = ok.WheelLayout(lever[:, None] * np.stack([np.cos(alpha), np.sin(alpha)], 1),
                                alpha + np.pi / 2, np.zeros(3), np.full(3, R_WHEEL))
        np.testing.assert_allclose(MODEL.jacobian(modes), ok.wheel_jacobian(layout),
                                   atol=1e-12)


@pytest.mark.parametrize("flip", [False, True])
def test_steady_turn_is_a_circle_newton_euler(flip, steady_turn_off_circle):
    """The hybrid model's ψ̇ cross-term against Newton–Euler in the world frame (see the
    fixture): a flipped term leaves the circle by centimetres within half a turn, against
    ~1e-7 m of RK4 at 5 ms (global error ~ ρ (r Δt)⁴ / 5 per radian)."""
    model = dataclasses.replace(MODEL, roller_axial=0.0)
    modes = (0, 0, 0)

    def accel(nu, tau):
        return model.body_acceleration(nu, np.full(3, np.pi), modes, tau)
    off = steady_turn_off_circle(accel, model.jacobian(modes), model.velocity_term,
                                 model.mass, flip)
    assert off > 0.01 if flip else off < 1e-6


def test_roller_term_conserves_energy():
    """d/dt ½νᵀM(θ)ν = τ·θ̇ only with the ∂k/∂φ term (the roller spin changes with the
    contact radius ρ(φ)). RK4 at 0.2 ms over 50 ms within one roller's contact: error
    ~1e-12 J; without the term the balance misses by the roller's spin-energy change."""
    model = dataclasses.replace(MODEL, roller_axial=1e-4)  # exaggerated to test the term
    modes = (3, 3, 3)
    th0 = np.full(3, -0.1)
    nu0 = np.array([0.05, 0.1, 0.1])
    tau = np.array([0.01, -0.02, 0.015])

    def rhs(s, with_term=True):
        nu, th = s[:3], s[3:6]
        nudot = model.body_acceleration(nu, th, modes, tau)
        if not with_term:
            H = model.jacobian(modes)
            nudot = np.linalg.solve(model.planar_mass(modes, th),
                                    H.T @ tau - model.velocity_term(nu))
        return np.concatenate([nudot, model.jacobian(modes) @ nu,
                               [tau @ model.jacobian(modes) @ nu]])

    for with_term, bound in ((True, 1e-10), (False, None)):
        s = np.concatenate([nu0, th0, [0.0]])
        dt = 2e-4
        for _ in range(250):
            k1 = rhs(s, with_term)
            k2 = rhs(s + 0.5 * dt * k1, with_term)
            k3 = rhs(s + 0.5 * dt * k2, with_term)
            k4 = rhs(s + dt * k3, with_term)
            s = s + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        assert model.modes(s[3:6]) == modes
        d_energy = (model.kinetic_energy(s[:3], modes, s[3:6])
                    - model.kinetic_energy(nu0, modes, th0))
        if bound is not None:
            assert abs(s[6] - d_energy) < bound
        else:
            assert abs(s[6] - d_energy) > 1e-6


def test_impact_is_the_metric_projection():
    """Carnot: the energy lost equals the kinetic energy of the velocity change, the
    result satisfies the new constraints, and it is the closest such velocity in 𝕄."""
    th = np.full(3, np.pi + np.pi / 12 + 1e-3)  # just past a hand-over on every wheel
    old, new = (0, 0, 0), MODEL.modes(th)
    assert new != old
    q = MODEL.lift(np.array([0.3, -0.1, 1.0]), old, th)
    q_plus, lost = MODEL.impact(q, new, th)
    A = MODEL.constraint_rows(new, th)
    np.testing.assert_allclose(A @ q_plus, 0.0, atol=1e-10)
    dq = q_plus - q
    assert lost == pytest.approx(0.5 * dq @ MODEL.full_mass() @ dq, rel=1e-9)
    assert lost == pytest.approx(MODEL.full_energy(q) - MODEL.full_energy(q_plus), rel=1e-9)
    null = np.linalg.svd(A)[2][A.shape[0]:]
    rng = np.random.default_rng(1)
    for _ in range(20):
        other = q_plus + null.T @ rng.normal(size=null.shape[0]) * 1e-3
        assert MODEL.full_energy(other - q) > MODEL.full_energy(q_plus - q)


def test_inplane_impact_pure_rotation_closed_form():
    """All wheels from row L − e to L + e in pure rotation; momentum along the new
    constraint is conserved: r⁺ (I_z + 3 I_w ℓ₊²/r²) = r⁻ (I_z + 3 I_w ℓ₊ℓ₋/r²)."""
    model = dataclasses.replace(MODEL, roller_axial=0.0)
    th = np.full(3, np.pi + np.pi / 12 + 1e-3)
    old, new = (0, 0, 0), model.modes(th)
    lp, lm = 0.15 - GEOM.offsets[new[0]], 0.15 - GEOM.offsets[0]
    assert lp > lm
    iw, iz = model.wheel_inertia, 0.0245
    nu_plus = model.inplane_impact(np.array([0.0, 0.0, 1.0]), old, new, th, np.zeros(3))
    expect = (iz + 3 * iw * lp * lm / R_WHEEL ** 2) / (iz + 3 * iw * lp ** 2 / R_WHEEL ** 2)
    np.testing.assert_allclose(nu_plus, [0.0, 0.0, expect], atol=1e-12)


def test_vertical_impulse_brakes_the_rolling_wheel():
    """Rolling over the cusp at a hand-over: the upward impulse at the contact ahead of
    the axle opposes the wheel's spin, so the planar energy drops; zero when the wheel
    does not turn (pure sideways roll of wheel 1 along x)."""
    th = np.full(3, np.pi + np.pi / 12 + 1e-3)
    old, new = (0, 0, 0), MODEL.modes(th)
    nu = np.array([0.0, 0.3, 0.0])
    J = MODEL.vertical_impulses(nu, old, new, th, np.zeros(3))
    rates = MODEL.jacobian(old) @ nu
    assert np.all(J * rates < 0)
    assert np.all(np.abs(J) > 0)


def test_remove_energy_takes_exactly_that_energy():
    th = np.full(3, np.pi)
    modes = MODEL.modes(th)
    nu = np.array([0.3, 0.0, 1.0])
    for energy in (1e-5, 1e-3):
        after = MODEL.remove_energy(nu, modes, th, 2, energy)
        assert (MODEL.kinetic_energy(nu, modes, th) - MODEL.kinetic_energy(after, modes, th)
                == pytest.approx(energy, rel=1e-9))


def test_handover_dissipation_is_the_contact_work():
    """½ N δ, N = M g / 3: a linear spring loaded to N over δ stores ½ N δ."""
    model = dataclasses.replace(MODEL, penetration=4e-5)
    assert model.handover_dissipation == pytest.approx(0.5 * 2.54 * 9.81 / 3 * 4e-5)


def test_drive_laws():
    servo = Drive("rate", torque_limit=1.0, gain=2.0)
    np.testing.assert_allclose(servo.torques(np.array([1.0, 0.0, 10.0]),
                                             np.array([0.9, 0.2, 0.0])), [0.2, -0.4, 1.0])
    torque = Drive("torque", torque_limit=0.5)
    np.testing.assert_allclose(torque.torques(np.array([0.1, -0.7, 0.5]), np.zeros(3)),
                               [0.1, -0.5, 0.5])


def test_servo_step_saturates_then_reaches_the_command():
    """A step to wheel rates u: the torque starts at its limit (k_v u ≫ τ_max), then
    θ̇ → u; after 0.8 s the twist is the commanded one within 3 mm/s (a hand-over's
    impulse dips the speed by ~1 mm/s and the servo's few-ms time constant restores it).
    """
    nu_cmd = np.array([0.3, 0.0, 0.0])
    rates = np.tile(ok.wheel_jacobian(ok.symmetric_layout(R_WHEEL, 0.15)) @ nu_cmd, (200, 1))
    run = simulate(dataclasses.replace(MODEL, roller_axial=0.0),
                   Drive("rate", 1.0, 2.0), rates, 0.004, np.zeros(3), np.zeros(3),
                   np.full(3, np.pi), substeps=2)
    assert np.max(np.abs(run.torques[0])) == pytest.approx(1.0)
    np.testing.assert_allclose(run.twist[-1][:2], nu_cmd[:2], atol=3e-3)


@pytest.mark.parametrize("kwargs, match", [
    ({"mode": "rate", "torque_limit": 0.0, "gain": 1.0}, "torque_limit"),
    ({"mode": "torque", "torque_limit": -1.0}, "torque_limit"),
    ({"mode": "torque", "torque_limit": float("nan")}, "torque_limit"),
    ({"mode": "rate", "torque_limit": 1.0, "gain": float("inf")}, "gain"),
    ({"mode": "speed", "torque_limit": 1.0}, "mode"),
])
def test_drive_rejects_bad_settings(kwargs, match):
    with pytest.raises(ValueError, match=match):
        Drive(**kwargs)


def test_simulate_rejects_non_finite_inputs():
    bad = np.zeros((5, 3))
    bad[2, 1] = np.nan
    with pytest.raises(ValueError, match="inputs"):
        simulate(MODEL, Drive("torque", 1.0), bad, 0.004, np.zeros(3), np.zeros(3),
                 np.zeros(3))


def test_normal_loads_moment_balance():
    """A push along x at the ground (r below the centre of mass) pitches the nose up:
    with ΣF_x the push, N₁ = Mg/3 − 2 r ΣF_x / (3L), N₂ = N₃ = Mg/3 + r ΣF_x / (3L)
    (moment balance about y with wheel 1 at x = L, wheels 2, 3 at x = −L/2)."""
    m = dataclasses.replace(MODEL, wheel_axial=1e-12)
    np.testing.assert_allclose(m.normal_loads(np.zeros(3), np.zeros(3)),
                               np.full(3, 2.54 * 9.81 / 3), rtol=1e-12)
    f = 2.0
    fx = math.sqrt(3) * f
    loads = m.normal_loads(np.array([0.0, -f, f]), np.zeros(3))
    w = 2.54 * 9.81 / 3
    np.testing.assert_allclose(loads, [w - 2 * R_WHEEL * fx / (3 * 0.15),
                                       w + R_WHEEL * fx / (3 * 0.15),
                                       w + R_WHEEL * fx / (3 * 0.15)], rtol=1e-9)


def test_slip_mode_transmits_coulomb_force():
    """A slipping wheel passes exactly its μN along its drive direction to the platform:
    with all wheels slipping, P ν̇ + c = r Hᵀ F (no wheel torque reaches the platform)."""
    m = dataclasses.replace(MODEL, roller_axial=0.0)
    modes = (0, 0, 0)
    nu = np.array([0.2, -0.1, 0.5])
    F = np.array([3.0, -2.0, 1.0])
    nudot, thdd, forces = m.accelerations(nu, np.full(3, np.pi), modes, np.full(3, 0.7),
                                          np.ones(3, dtype=bool), F)
    P = np.diag([2.54, 2.54, 0.0245])
    np.testing.assert_allclose(P @ nudot + m.velocity_term(nu),
                               R_WHEEL * m.jacobian(modes).T @ F, atol=1e-12)
    np.testing.assert_allclose(thdd, (0.7 - R_WHEEL * F) / m.wheel_inertia)
    np.testing.assert_allclose(forces, F)


def test_overlap_impulse_from_window_and_friction():
    """Both rows touch over Δφ_w = δ/|x_c| of wheel turn; the pair carries μN/4 (Coulomb,
    fast turning) or the soft contact's (N/g)(2/t_c) e|r| (slow turning) at levers L ± e:
    yaw impulse 2 e f Δφ_w / |θ̇|. Numbers typed from the geometry above."""
    delta, tc = 4e-5, 0.008
    m = dataclasses.replace(MODEL, penetration=delta, contact_timeconst=tc, friction=1.0)
    th = np.full(3, np.pi + np.pi / 12 + 1e-3)
    modes = m.modes(th)
    phi = float(GEOM.phases(th[0])[modes[0]])
    xc = abs(GEOM.contact_ahead(phi))
    load = 2.54 * 9.81 / 3
    for r, rate in ((1.0, 8.0), (0.05, 8.0)):
        nu = np.array([0.3, 0.0, r])
        force = min(load / 4, load / 9.81 * 2 / tc * E * r)
        expect = 2 * E * force * (delta / xc) / rate
        assert m.overlap_impulse(nu, modes, th, 0, rate) == pytest.approx(expect, rel=1e-9)
    assert MODEL.overlap_impulse(np.array([0.3, 0.0, 1.0]), modes, th, 0, 8.0) == 0.0


def test_arc_moment_is_the_weight_potential_gradient():
    """The normal-load moment −N x_c(φ) on each wheel is −∂V/∂θ_i of the weight's
    potential V = N Σ R(φ_i) (N = M g / 3): check against a finite difference of V,
    passed to the platform through Hᵀ."""
    m = dataclasses.replace(MODEL, roller_axial=0.0)
    th = np.array([np.pi + 0.1, np.pi - 0.2, np.pi + 0.05])
    modes = m.modes(th)
    load = np.full(3, 2.54 * 9.81 / 3)
    nu, tau, none = np.zeros(3), np.zeros(3), np.zeros(3, dtype=bool)
    with_arc = m.accelerations(nu, th, modes, tau, none, np.zeros(3), load)[0]
    grad = np.zeros(3)
    for i in range(3):
        d = np.zeros(3)
        d[i] = 1e-6
        v_plus = sum(load[k] * GEOM.rolling_radius(float(GEOM.phases((th + d)[k])[modes[k]]))
                     for k in range(3))
        v_minus = sum(load[k] * GEOM.rolling_radius(float(GEOM.phases((th - d)[k])[modes[k]]))
                      for k in range(3))
        grad[i] = (v_plus - v_minus) / 2e-6
    expect = np.linalg.solve(m.planar_mass(modes, th), m.jacobian(modes).T @ (-grad))
    np.testing.assert_allclose(with_arc, expect, atol=1e-6 * np.max(np.abs(expect)))


def test_batch_members_equal_their_single_runs():
    """simulate_batch vectorises the runs: a rate-servo and a torque run integrated
    together give what each gives alone (no cross-talk between members)."""
    drives = [Drive("rate", 0.5, gain=0.5), Drive("torque", 0.5)]
    inputs = np.stack([np.tile([6.0, -3.0, 2.0], (60, 1)), np.tile([0.02, 0.0, -0.02],
                                                                    (60, 1))])
    th0 = np.array([[0.1, 0.2, 0.3], [1.0, 2.0, 3.0]])
    both = simulate_batch(MODEL, drives, inputs, 0.004, np.zeros((2, 3)), np.zeros((2, 3)),
                          th0)
    for b in range(2):
        alone = simulate(MODEL, drives[b], inputs[b], 0.004, np.zeros(3), np.zeros(3), th0[b])
        np.testing.assert_allclose(both[b].twist, alone.twist, rtol=0, atol=1e-12)
        assert both[b].switches == alone.switches
    assert both[0].switches  # the rate run hands over rollers within the window


def test_closed_form_roller_derivative_matches_a_numerical_one():
    """∂k/∂φ of the contact roller (closed form) against a central difference of k over
    the wheel angle (∂φ/∂θ = 1), across a roller's arc: agreement to the difference's
    O(ε²) truncation."""
    for theta in np.linspace(0.05, 0.4, 6):
        th = np.full(3, theta)
        modes = MODEL.modes(th)
        _k, dk = MODEL.roller_rows(modes, th)
        eps = 1e-6
        num = (MODEL.roller_rows(modes, th + eps)[0] - MODEL.roller_rows(modes, th - eps)[0])
        np.testing.assert_allclose(dk, num / (2 * eps), rtol=1e-6, atol=1e-6)


def test_hand_overs_are_located_within_the_step():
    """A step that crosses a hand-over is cut at it (|φ_old| = |φ_new|), so the hybrid
    integration converges at the RK4 order across switches: a torque run over several
    hand-overs (no impacts, so only the switch instant of the lever L ± e matters) at one
    4 ms step per output step agrees with 16 substeps to 1e-6 m; applying the switch at
    the step's end instead would shift each switch by up to 4 ms, ~1e-5 m per switch at
    these speeds."""
    inputs = np.tile([0.05, 0.05, 0.05], (150, 1))
    args = (MODEL, Drive("torque", 1.0), inputs, 0.004, np.zeros(3), np.zeros(3),
            np.array([0.1, 0.3, 0.5]))
    coarse = simulate(*args, substeps=1, impacts=False, slip=False)
    fine = simulate(*args, substeps=16, impacts=False, slip=False)
    assert len(fine.switches) >= 6
    np.testing.assert_allclose(coarse.pose, fine.pose, atol=1e-6)


def test_relaxed_hand_over_leaves_rho_to_the_m_of_the_jump():
    """A soft contact makes a hand-over's jump over several steps: with ``relax`` ρ the
    reported twist differs from the rigid run's by a transient that shrinks by ρ every
    step between hand-overs and grows by ρ (ν⁻ − ν⁺) at each, ν⁺ − ν⁻ the rigid run's
    jump over that step less its continuous change (bounded by the largest change over a
    step without a hand-over, the tolerance there, times ρ); the pose differs by the
    transient's running sum times Δt (pure rotation: heading). The dynamics are the rigid
    run's (wheel angles identical). Other tolerances: 1e-12, rounding."""
    rho, dt = 0.5, 0.001
    inputs = np.tile([0.02, 0.02, 0.02], (1000, 1))
    args = (MODEL, Drive("torque", 1.0), inputs, dt, np.zeros(3), np.zeros(3),
            np.array([0.1, 0.1, 0.1]))
    rigid = simulate(*args, substeps=1, slip=False)
    soft = simulate(*args, substeps=1, slip=False, relax=rho)
    np.testing.assert_array_equal(soft.thetas, rigid.thetas)
    diff = soft.twist - rigid.twist
    steps = sorted({round(t / dt) for t, _, _ in rigid.switches})
    assert len(steps) >= 4
    # Between hand-overs: a geometric decay by ρ.
    quiet = [k for k in range(steps[0] + 1, len(diff)) if k not in steps]
    np.testing.assert_allclose(diff[quiet], rho * diff[[k - 1 for k in quiet]],
                               rtol=0, atol=1e-12)
    # At a hand-over: ρ times the rigid jump, reversed.
    quiet_change = np.abs(np.diff(rigid.twist[:, 2]))[[k - 1 for k in quiet]].max()
    for k in steps:
        jump = rigid.twist[k, 2] - rigid.twist[k - 1, 2]
        assert abs(jump) > 10 * quiet_change
        assert diff[k, 2] - rho * diff[k - 1, 2] == pytest.approx(-rho * jump,
                                                                  abs=rho * quiet_change)
    # Pure rotation: the heading lags by Δt Σ of the yaw-rate transient.
    np.testing.assert_allclose(soft.pose[:, 2] - rigid.pose[:, 2],
                               dt * np.cumsum(diff[:, 2]), rtol=0, atol=1e-12)
    # ρ = 0 is the rigid impact, bit for bit.
    np.testing.assert_array_equal(simulate(*args, substeps=1, slip=False, relax=0.0).twist,
                                  rigid.twist)


@pytest.mark.parametrize("relax", [1.0, -1.0, math.nan])
def test_relax_outside_its_range_is_refused(relax):
    with pytest.raises(ValueError, match="relax"):
        simulate(MODEL, Drive("torque", 1.0), np.zeros((3, 3)), 0.004, np.zeros(3),
                 np.zeros(3), np.zeros(3), relax=relax)


def test_batch_members_are_their_single_runs_to_the_bit():
    """With the settings ``wmr validate`` uses (slip, arc, heave, relaxed hand-overs) a
    member of a batch is its run alone, float for float: the hand-over's RK4 and the rest
    of the step are taken by the runs that hand over, and the others keep their step
    (what lets omni3 batch its families together, :mod:`wmr_mujoco.validation.units`)."""
    drives = [Drive("rate", 0.5, gain=0.5), Drive("torque", 0.5), Drive("rate", 0.5, gain=0.5),
              Drive("torque", 0.5)]
    # The last run rests under zero torques from a start of −0.0 (pose, twist, wheels):
    # signed zeros that a step of another run's hand-over must leave as they are.
    inputs = np.stack([np.tile([6.0, -3.0, 2.0], (150, 1)),
                       np.tile([0.02, 0.0, -0.02], (150, 1)),
                       np.tile([-4.0, 5.0, 1.0], (150, 1)),
                       np.full((150, 3), -0.0)])
    th0 = np.array([[0.1, 0.2, 0.3], [1.0, 2.0, 3.0], [0.5, -0.4, 2.2], [-0.0, -0.0, -0.0]])
    start = np.zeros((4, 3))
    start[3] = -0.0
    kw = {"substeps": 2, "arc": True, "heave": True, "relax": 0.3}
    both = simulate_batch(MODEL, drives, inputs, 0.004, start, start, th0, **kw)
    for b in range(4):
        alone = simulate_batch(MODEL, drives[b:b + 1], inputs[b:b + 1], 0.004,
                               start[b:b + 1], start[b:b + 1], th0[b:b + 1], **kw)[0]
        for field in ("t", "pose", "twist", "thetas", "torques"):
            # The bytes: == would take −0.0 for +0.0
            a, c = getattr(both[b], field), getattr(alone, field)
            assert a.shape == c.shape and a.dtype == c.dtype == np.float64
            np.testing.assert_array_equal(np.ascontiguousarray(a).view(np.uint64),
                                          np.ascontiguousarray(c).view(np.uint64))
        assert both[b].switches == alone.switches
    assert np.signbit(both[3].pose[0]).all()  # the −0.0 start is kept (and compared)
    steps = [{round(t / 0.004) for t, _, _ in run.switches} for run in both]
    assert steps[0] and steps[2] and steps[0] != steps[2]  # hand-overs at other steps
