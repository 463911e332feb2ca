"""Judged metrics of the Whipple model, the linear push reference and the figure."""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

from wmr_mujoco import whipple_validation as wv
from wmr_mujoco.analytic import whipple as wa
from wmr_mujoco.whipple_params import WhippleParams


def test_all_metrics_pass_at_defaults():
    metrics = wv.all_metrics(WhippleParams())
    failed = [m for m in metrics if not wv.passed(m)]
    assert not failed, failed
    for _, value, unit, _, kind in metrics:
        assert np.isfinite(value) and unit and kind


def test_linear_lean_matches_ode_integration():
    """The matrix-exponential response equals an adaptive ODE solution (rtol 1e-10) to
    1e-7 rad."""
    p = WhippleParams()
    times = np.arange(0.0, 5.0, 0.01)
    got = wv.linear_lean(p, 5.0, times)
    a = wa.state_matrix(5.0, wa.matrices(p))
    sol = solve_ivp(lambda t, x: a @ x, (0, times[-1]), [0, 0, wv.PUSH_LEAN_RATE, 0],
                    t_eval=times, rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(got, sol.y[0], atol=1e-7)


def test_passed_reads_growth_and_bounds():
    assert wv.passed(("x", 0.05, "1", 0.1, "requirement"))
    assert not wv.passed(("x", 0.2, "1", 0.1, "requirement"))
    assert wv.passed(("x", 3.0, "1", 1.0, "requirement: > 1 (grows)"))
    assert not wv.passed(("x", 0.5, "1", 1.0, "requirement: > 1 (grows)"))


def test_figure_written(tmp_path):
    series = wv.eigen_series(WhippleParams(), [2.0, 6.0], np.linspace(0, 10, 21))
    assert series["physics_eig"].shape == (2, 4)
    path = wv.write_figure(tmp_path / "eig.png", series)
    assert path.stat().st_size > 10_000
