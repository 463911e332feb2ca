"""The rolling-disc equations against independent derivations and published results."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from wmr_mujoco.analytic.integrate import rk4_step
from wmr_mujoco.analytic.rolling_disc import RollingDisc

A_RAD, MASS = 0.15, 1.5
# The package's wheel: uniform disc 20 mm thick (A has the m w²/12 term).
DISC = RollingDisc(A_RAD, MASS, 0.5 * MASS * A_RAD**2, MASS * (A_RAD**2 / 4 + 0.02**2 / 12))
# Ideal thin uniform disc, for the published closed forms.
THIN = RollingDisc(A_RAD, MASS, 0.5 * MASS * A_RAD**2, 0.25 * MASS * A_RAD**2)


def frame(psi, th):
    e1 = np.array([math.cos(psi), math.sin(psi), 0.0])
    e2 = np.array([-math.sin(psi) * math.cos(th), math.cos(psi) * math.cos(th), math.sin(th)])
    return e1, e2, np.cross(e1, e2)


def test_rhs_matches_newton_euler_with_the_contact_force_unknown():
    """Independent derivation: world-frame Newton–Euler, unknowns (ω̇, a_G, F), 9 equations.

    m a_G = F − m g ẑ;  I ω̇ + ω × I ω = (−r) × F;  a_G = ω̇ × r + ω × (Ω × r), r = a ê3,
    Ω = ψ̇ ẑ + θ̇ ê1 the frame rate. Tolerance 1e-9: both are exact up to round-off.
    """
    d = DISC
    rng = np.random.default_rng(3)
    for _ in range(5):
        state = np.concatenate([[0.1, -0.2], rng.uniform(-1, 1, 2) * [3, 1.2], [0.3],
                                rng.uniform(-8, 8, 3)])
        psi, th = state[2], state[3]
        e1, e2, e3 = frame(psi, th)
        w = state[5] * e1 + state[6] * e2 + state[7] * e3
        dx = d.rhs(0.0, state)
        big_omega = dx[2] * np.array([0, 0, 1.0]) + dx[3] * e1
        rot = np.column_stack([e1, e2, e3])
        inertia = rot @ np.diag([d.diametral_inertia, d.axial_inertia,
                                 d.diametral_inertia]) @ rot.T
        r = d.radius * e3

        def skew(v):
            return np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
        # unknowns z = (ω̇, a_G, F)
        m = np.zeros((9, 9))
        rhs = np.zeros(9)
        m[0:3, 3:6] = d.mass * np.eye(3)
        m[0:3, 6:9] = -np.eye(3)
        rhs[0:3] = [0, 0, -d.mass * d.gravity]
        m[3:6, 0:3] = inertia
        m[3:6, 6:9] = skew(r)  # (−r) × F moved left: + r × F
        rhs[3:6] = -np.cross(w, inertia @ w)
        m[6:9, 0:3] = -skew(r)  # ω̇ × r = −r × ω̇
        m[6:9, 3:6] = -np.eye(3)
        rhs[6:9] = -np.cross(w, np.cross(big_omega, r))
        z = np.linalg.solve(m, rhs)
        wdot_ne = z[0:3]
        wdot = dx[5] * e1 + dx[6] * e2 + dx[7] * e3 + np.cross(big_omega, w)
        assert wdot == pytest.approx(wdot_ne, abs=1e-9)


def test_energy_is_conserved_to_1e_9_over_10_s():
    """Rolling without slip does no work: E constant. 1e-9 relative: the ODE solved at
    rtol 1e-12 accumulates error far below that over 10 s."""
    x0 = DISC.initial_state(0.15, 1.0)
    sol = solve_ivp(DISC.rhs, (0, 10), x0, method="DOP853", rtol=1e-12, atol=1e-12,
                    t_eval=np.linspace(0, 10, 201))
    e = DISC.energy(sol.y.T)
    assert np.max(np.abs(e / e[0] - 1)) < 1e-9


def test_rolling_constraint_holds_along_a_trajectory():
    """The contact point of the disc is at rest: dG/dt (finite differences of the centre
    along the solution) equals ω × (a ê3) with ω = ψ̇ ẑ + θ̇ ê1 + φ̇ ê2 from the angle rates.
    Central differences at h = 1 ms: error O(h² |G'''|) < 1e-5 m/s."""
    x0 = DISC.initial_state(0.3, 1.2, lean_rate=0.5)
    h = 1e-3
    x, states = x0, [x0]
    for _ in range(20000):
        x = rk4_step(lambda s, _u: DISC.rhs(0.0, s), x, np.zeros(0), h / 10)
        states.append(x)
    rows = np.asarray(states)[::10]
    g = DISC.centre(rows)
    v_fd = (g[2:] - g[:-2]) / (2 * h)
    worst = 0.0
    for k in range(1, len(rows) - 1):
        s = rows[k]
        dx = DISC.rhs(0.0, s)
        e1, e2, e3 = frame(s[2], s[3])
        w = dx[2] * np.array([0, 0, 1.0]) + dx[3] * e1 + dx[4] * e2
        worst = max(worst, np.linalg.norm(v_fd[k - 1] - np.cross(w, DISC.radius * e3)))
    assert worst < 1e-5


def test_steady_motion_is_an_exact_equilibrium():
    sm = DISC.steady_motion(0.3, 0.6)
    dx = DISC.rhs(0.0, sm.state)
    assert dx[3] == 0.0 and np.abs(dx[5:]).max() < 1e-12
    assert dx[2] == pytest.approx(sm.heading_rate, rel=1e-12)
    # One full circle of the nonlinear ODE: lean and contact radius held to 1e-8.
    sol = solve_ivp(DISC.rhs, (0, sm.period), sm.state, method="DOP853", rtol=1e-11,
                    atol=1e-12, t_eval=np.linspace(0, sm.period, 100))
    assert np.abs(sol.y[3] - 0.3).max() < 1e-8
    dist = np.hypot(sol.y[0], sol.y[1] + 0.6)
    assert np.abs(dist - 0.6).max() < 1e-8


def test_steady_lean_inverts_steady_motion():
    sm = DISC.steady_motion(0.4, 0.8)
    assert DISC.steady_lean(sm.spin_rate, sm.heading_rate) == pytest.approx(0.4, abs=1e-9)
    assert DISC.steady_residual(0.4, sm.heading_rate, sm.w2) == pytest.approx(0, abs=1e-12)


def test_coin_spinning_in_place_matches_published_rate():
    """Centre at rest (contact circle R = a sin θ): Ω² = 4 g / (a sin α), α = π/2 − θ the
    angle between disc and floor (thin uniform disc; e.g. Moffatt, Nature 404, 2000)."""
    th = 0.5
    sm = THIN.steady_motion(th, A_RAD * math.sin(th))
    assert sm.heading_rate**2 == pytest.approx(4 * 9.81 / (A_RAD * math.cos(th)), rel=1e-12)
    assert sm.centre_radius == pytest.approx(0.0, abs=1e-15)


def test_critical_speed_of_a_thin_disc_is_sqrt_ga_over_3():
    """Published: a thin uniform disc rolls upright stably above v² = g a / 3."""
    assert THIN.critical_speed == pytest.approx(math.sqrt(9.81 * A_RAD / 3), rel=1e-12)


@pytest.mark.parametrize("ratio", [0.7, 1.3])
def test_upright_linearisation_eigenvalues_match_the_stability_formula(ratio):
    """Jacobian of the full ODE at upright rolling (central differences, 1e-6): its
    eigenvalues are 0 and ±√λ² with λ² from lean_rate_squared (tolerance 1e-5 of the
    scale √(m g a/(A + m a²)) ≈ 7/s, finite-difference error ~1e-10)."""
    spin = ratio * DISC.critical_spin
    x0 = np.array([0, 0, 0, 0, 0, 0, spin, 0.0])
    idx = [3, 5, 7]  # θ, ω1, ω3: the lean subsystem
    jac = np.zeros((3, 3))
    for j, i in enumerate(idx):
        dx = np.zeros(8)
        dx[i] = 1e-6
        jac[:, j] = ((DISC.rhs(0, x0 + dx) - DISC.rhs(0, x0 - dx)) / 2e-6)[idx]
    def order(z):
        return sorted(z, key=lambda c: (round(c.real, 4), round(c.imag, 4)))
    eig = order(np.linalg.eigvals(jac))
    lam2 = DISC.lean_rate_squared(spin)
    expect = order([0j, np.sqrt(complex(lam2)), -np.sqrt(complex(lam2))])
    assert np.array(eig) == pytest.approx(np.array(expect), abs=1e-5)
    assert (lam2 < 0) == (ratio > 1)


def test_incline_matches_lagrange_with_rolling_constraint():
    """L = ½ m ẋ² + ½ C θ̇² + m g x sin β, constraint ẋ − a θ̇ = 0 with multiplier λ:
    m ẍ = m g sin β + λ, C θ̈ = −a λ, ẍ = a θ̈. Also the classic (2/3) g sin β."""
    beta = 0.2
    d = DISC
    a_mat = np.array([[d.mass, 0, -1], [0, d.axial_inertia, d.radius], [1, -d.radius, 0]])
    xdd, _, _ = np.linalg.solve(a_mat, [d.mass * 9.81 * math.sin(beta), 0, 0])
    assert d.incline_acceleration(beta) == pytest.approx(xdd, rel=1e-12)
    assert THIN.incline_acceleration(beta) == pytest.approx(2 / 3 * 9.81 * math.sin(beta))


@pytest.mark.parametrize("call, match", [
    (lambda: DISC.initial_state(1.6, 1.0), r"lean = 1.6 rad .* valid range is \(-1.5708"),
    (lambda: DISC.initial_state(0.1, -1.0), r"speed = -1.0 m/s .* valid range is \[0, inf\)"),
    (lambda: DISC.initial_state(0.1, math.nan), r"speed = nan"),
    (lambda: DISC.incline_acceleration(math.pi / 2), r"incline = 1.5707.*\(below 90°\)"),
    (lambda: DISC.lean_rate_squared(-3.0), r"spin = -3.0 rad/s"),
    (lambda: DISC.steady_motion(0.3, 0.01), r"radius = 0.01 m has no steady motion"),
    (lambda: DISC.steady_motion(-0.3, 0.5), r"lean = -0.3 rad; steady circling"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
