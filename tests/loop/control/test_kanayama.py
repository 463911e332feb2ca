"""Kanayama et al. (1990) trajectory tracking closing the loop on the unicycle model."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.linalg import expm

from wmr_mujoco.loop.control import paths
from wmr_mujoco.loop.control.base import Trajectory
from wmr_mujoco.loop.control.kanayama import Kanayama


def test_linear_matrix_is_the_jacobian_of_the_error_dynamics():
    """The error dynamics of the paper (ė_x = ω e_y − v + v_r cos e_θ, ė_y = −ω e_x +
    v_r sin e_θ, ė_θ = ω_r − ω with the law substituted), differentiated numerically at zero
    error (central differences, O(h²) = 1e-12), against the stated linear matrix."""
    c = Kanayama()
    vr, wr = 0.5, 0.25

    def f(e):
        ex, ey, et = e
        v = vr * math.cos(et) + c.k_x * ex
        w = wr + vr * (c.k_y * ey + c.k_theta * math.sin(et))
        return np.array([w * ey - v + vr * math.cos(et), -w * ex + vr * math.sin(et), wr - w])
    h = 1e-6
    jac = np.stack([(f(h * e) - f(-h * e)) / (2 * h) for e in np.eye(3)], 1)
    np.testing.assert_allclose(c.linear_matrix(vr, wr), jac, atol=1e-8)


@pytest.mark.parametrize("path", [paths.line(30.0), paths.circle(2.0)])
def test_small_errors_follow_the_linear_solution(loop, path):
    """Start 1 cm and 0.02 rad off the reference: the errors follow e(t) = exp(A t) e₀ with
    A the paper's linear error matrix (written out here: straight line ω_r = 0, circle
    ω_r = v_r/R). Nonlinear terms are O(|e₀|²) ≈ 2 % of e₀, the 5 ms hold O(v_r √K_y Δt)
    = 1 %: within 5 % of |e₀| at every sample, and the final error (t = 4 s, when the
    solution is down to ≈ 0.3 % of e₀) below 1 % of |e₀|."""
    vr, kx, ky = 0.5, 2.0, 16.0
    kt = 2 * math.sqrt(ky)
    c = Kanayama(k_x=kx, k_y=ky)
    ref = Trajectory(path, vr)
    start = ref.at(0.0)[0].pose + np.array([0.0, -0.01, 0.02])
    t, poses, _ = loop(c, ref, start, 4.0, 0.005)
    errs = np.array([c.errors(p, ref.at(tk)[0].pose) for tk, p in zip(t, poses, strict=True)])
    wr = vr * path.curvature[0]
    a = np.array([[-kx, wr, 0.0], [-wr, 0.0, vr], [0.0, -vr * ky, -vr * kt]])
    expected = np.array([expm(a * tk) @ errs[0] for tk in t])
    np.testing.assert_allclose(errs, expected, atol=0.05 * np.linalg.norm(errs[0]))
    assert np.linalg.norm(errs[-1]) < 0.01 * np.linalg.norm(errs[0])


def test_car_follows_through_the_steering_angle(loop):
    """A car (wheelbase 0.5 m, δ = atan(ℓ ω / v)) on the circle converges like the unicycle
    (the same ψ̇): the error after 6 s is below 1 mm from a 5 cm start."""
    c = Kanayama(wheelbase=0.5)
    ref = Trajectory(paths.circle(2.0), 0.5)
    _, poses, _ = loop(c, ref, [0.0, -0.05, 0.0], 6.0, 0.005, 0.5)
    assert np.hypot(*(poses[-1, :2] - ref.at(6.0)[0].position)) < 1e-3
