import numpy as np
import pytest

from wmr_mujoco.analytic import bicycle, constraints, unicycle
from wmr_mujoco.analytic.integrate import integrate
from wmr_mujoco.robots.tricycle import analytic as tricycle

DT = 0.002


def _check(pfaffian, rhs, q0, inputs, **geometry):
    """Residual of an integrated trajectory, with q̇ from the model and from differences."""
    traj = integrate(rhs, q0, inputs, DT)
    qdot_model = np.stack([rhs(q, u) for q, u in zip(traj[:-1], inputs, strict=True)])
    exact = constraints.residual(pfaffian, traj[:-1], qdot_model, **geometry)
    # Central differences: O(Δt²) error, ≈ Δt²/6 |q⃛| ≲ 1e-6 m/s for these inputs.
    fd = (traj[2:] - traj[:-2]) / (2 * DT)
    approx = constraints.residual(pfaffian, traj[1:-1], fd, **geometry)
    return np.max(np.abs(exact)), np.max(np.abs(approx))


def test_disc_constraints_hold():
    R = 0.15

    def rhs(q, u):
        return np.concatenate([unicycle.rates(q[:3], u), [u[0] / R]])

    t = np.arange(2500) * DT
    inputs = np.stack([1.0 + 0.3 * np.sin(t), 0.8 * np.cos(0.7 * t)], axis=1)
    exact, fd = _check(constraints.disc, rhs, np.zeros(4), inputs, radius=R)
    assert exact < 1e-14 and fd < 1e-5


def test_bicycle_constraints_hold():
    ell, rr, rf = 1.05, 0.34, 0.3

    def rhs(q, u):
        v, phi = u[0], q[3]
        return np.concatenate([bicycle.rates(q[:4], u, ell), [v / rr, v / np.cos(phi) / rf]])

    t = np.arange(2500) * DT
    inputs = np.stack([2.0 * np.ones_like(t), 0.4 * np.cos(t)], axis=1)
    exact, fd = _check(constraints.bicycle, rhs, np.zeros(6), inputs, wheelbase=ell,
                       rear_radius=rr, front_radius=rf)
    assert exact < 1e-13 and fd < 1e-5


def test_tricycle_constraints_hold():
    ell, w, rr, rf = 0.5, 0.4, 0.1, 0.12

    def rhs(q, u):
        v, phi = u[0], q[3]
        vl, vr = tricycle.rear_wheel_speeds(v, phi, w, ell)
        vf = tricycle.front_wheel_speed(v, phi)
        return np.concatenate([tricycle.rates(q[:4], u, ell), [vl / rr, vr / rr, vf / rf]])

    t = np.arange(2500) * DT
    inputs = np.stack([np.ones_like(t), 0.5 * np.sin(1.3 * t)], axis=1)
    exact, fd = _check(constraints.tricycle, rhs, np.zeros(7), inputs, wheelbase=ell, track=w,
                       rear_radius=rr, front_radius=rf)
    assert exact < 1e-13 and fd < 1e-5


def test_residual_measures_slip():
    q = np.array([[0.0, 0.0, 0.3, 0.0]])
    side = 0.2 * np.array([[np.sin(0.3), -np.cos(0.3), 0.0, 0.0]])
    res = constraints.residual(constraints.disc, q, side, radius=0.1)
    np.testing.assert_allclose(res, [[0.2, 0.0]], atol=1e-15)


def test_lecture_front_wheel_row():
    """Front lateral row equals the lecture's ẋ s(ψ+φ) − ẏ c(ψ+φ) − ℓ ψ̇ cos φ."""
    psi, phi, ell = 0.4, -0.3, 1.2
    A = constraints.bicycle(np.array([0, 0, psi, phi, 0, 0]), ell, 0.3, 0.3)
    qd = np.array([0.7, -0.2, 0.5, 0.0, 0.0, 0.0])
    lecture = (qd[0] * np.sin(psi + phi) - qd[1] * np.cos(psi + phi)
               - ell * qd[2] * np.cos(phi))
    assert A[1] @ qd == pytest.approx(lecture)


@pytest.mark.parametrize("call, match", [
    (lambda: constraints.disc([0, 0, 0], 0.1), r"q must have shape \(4,\), got \(3,\)"),
    (lambda: constraints.disc([0, 0, 0, 0], -0.1), "radius = -0.1"),
    (lambda: constraints.tricycle(np.zeros(7), 0.5, 0.0, 0.1, 0.1), "track = 0.0"),
    (lambda: constraints.residual(constraints.disc, np.zeros((5, 4)), np.zeros((4, 4)),
                                  radius=0.1), r"qdot must have shape \(5, 4\)"),
    (lambda: unicycle.rates([0, 0, np.inf], [1, 0]), "q contains non-finite"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
