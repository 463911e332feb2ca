"""Helpers shared by the analytic tests."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pytest

from wmr_mujoco.analytic import omni_kinematics as ok

Accel = Callable[[np.ndarray, np.ndarray], np.ndarray]


def _steady_turn_off_circle(accel: Accel, H: np.ndarray, c_term: Callable[[np.ndarray],
                            np.ndarray], mass: float, flip: bool) -> float:
    """Newton–Euler in the world frame: a platform at speed u turning at r moves on a
    circle of radius u/r only if the net force is the centripetal M u r towards the
    centre. Torques τ = H⁻ᵀ c(ν) (c flipped if ``flip``) hold ν̇ = 0 in the model;
    integrate the WORLD path over half a turn and return its distance off that circle, m.

    Also checks that ``c(ν)`` equals the centripetal force derived in the world frame
    (``M u²/ρ`` towards the centre, on the body's left for u, r > 0), sign included.
    """
    nu0 = np.array([0.3, 0.0, 1.0])
    sign = -1.0 if flip else 1.0
    f_world = np.array([0.0, mass * nu0[0] ** 2 / (nu0[0] / nu0[2]), 0.0])
    tau = np.linalg.solve(H.T, sign * c_term(nu0))
    np.testing.assert_allclose(H.T @ tau, sign * f_world, atol=1e-12)
    x = np.array([0.0, 0.0, 0.0, *nu0])
    dt = 5e-3

    def f(s: np.ndarray) -> np.ndarray:
        return np.concatenate([ok.body_to_world(s[2], s[3:]), accel(s[3:], tau)])

    for _ in range(int(np.pi / dt)):  # half a circle
        k1 = f(x)
        k2 = f(x + 0.5 * dt * k1)
        k3 = f(x + 0.5 * dt * k2)
        k4 = f(x + dt * k3)
        x = x + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    radius = nu0[0] / nu0[2]
    return float(abs(np.hypot(x[0], x[1] - radius) - radius))


@pytest.fixture
def steady_turn_off_circle() -> Callable[..., float]:
    """:func:`_steady_turn_off_circle`: the ψ̇ cross-term's sign check of a planar model."""
    return _steady_turn_off_circle
