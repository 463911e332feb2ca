import numpy as np
import pytest

from wmr_mujoco.analytic import omni_kinematics as ok
from wmr_mujoco.analytic.integrate import integrate
from wmr_mujoco.analytic.omni_dynamics import OmniDynamics

OMNI = OmniDynamics(mass=3.0, yaw_inertia=0.06, wheel_inertia=2e-4,
                    layout=ok.symmetric_layout(0.04, 0.15))


def test_reduced_equations_match_multipliers(rng):
    for _ in range(50):
        nu, tau = rng.normal(size=3), rng.normal(size=3)
        nudot = OMNI.body_acceleration(nu, tau)
        nudot_m, thdd_m, lam = OMNI.multiplier_solution(nu, tau)
        np.testing.assert_allclose(nudot, nudot_m, rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(thdd_m, OMNI.H @ nudot, rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(lam / OMNI.layout.radii, OMNI.traction_forces(nu, tau),
                                   rtol=1e-9, atol=1e-12)


def _energy_error(model, mass_matrix):
    """|∫ τ·θ̇ dt − ΔT| / ΔT for 3 s of varying torques, the work integrated as a state."""
    def rhs(x, tau):
        nu = x[3:6]
        nudot = np.linalg.solve(mass_matrix, model.H.T @ tau - model.velocity_term(nu))
        return np.concatenate([ok.body_to_world(x[2], nu), nudot, [tau @ model.H @ nu]])

    t = np.arange(1500) * 0.002
    taus = 0.02 * np.stack([np.sin(t), np.cos(2 * t), 1 + 0 * t], axis=1)
    x0 = np.array([0, 0, 0, 0.3, -0.2, 1.0, 0.0])
    traj = integrate(rhs, x0, taus, 0.002)
    d_energy = model.kinetic_energy(traj[-1, 3:6]) - model.kinetic_energy(x0[3:6])
    return abs(traj[-1, 6] - d_energy) / abs(d_energy)


def test_energy_balance():
    """Work of the torques equals the change of kinetic energy (RK4, Δt 2 ms: ~1e-12)."""
    assert _energy_error(OMNI, OMNI.mass_matrix) < 1e-9


def test_energy_balance_detects_missing_wheel_inertia():
    assert _energy_error(OMNI, OMNI.platform_matrix) > 1e-3


def test_naive_substitution_disagrees_with_multipliers():
    """Substituting θ̇ = H ν into the Lagrangian puts wheel inertia into the r-term too.
    That conserves energy as well (the r-term does no work), but the multiplier form
    shows it is wrong whenever the platform turns while translating."""
    extra = OMNI.wheel_inertia * (OMNI.H.T @ OMNI.H)[0, 0]
    nu, tau = np.array([0.5, -0.3, 2.0]), np.array([0.01, -0.02, 0.03])
    naive = np.linalg.solve(OMNI.mass_matrix, OMNI.H.T @ tau
                            - OMNI.velocity_term(nu) * (OMNI.mass + extra) / OMNI.mass)
    exact = OMNI.multiplier_solution(nu, tau)[0]
    assert np.linalg.norm(naive - exact) > 0.01 * np.linalg.norm(exact)
    np.testing.assert_allclose(OMNI.body_acceleration(nu, tau), exact, rtol=1e-9)


@pytest.mark.parametrize("call, match", [
    (lambda: OMNI.body_acceleration([0, 0, 0], [1, 2]), r"torques must have shape \(3,\)"),
    (lambda: OmniDynamics(1.0, 1.0, 1.0, layout="lecture"), "layout must be a WheelLayout"),
    (lambda: OmniDynamics(-1.0, 1.0, 1.0, layout=OMNI.layout), "mass = -1.0"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
