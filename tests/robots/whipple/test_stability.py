"""Self-stability after a push: the physics, the linear benchmark response, the bound."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from wmr_mujoco.robots.whipple import analytic as wa
from wmr_mujoco.robots.whipple import stability as st
from wmr_mujoco.robots.whipple.params import WhippleParams
from wmr_mujoco.robots.whipple.rolling import compile_model


@pytest.fixture(scope="module")
def model():
    return compile_model(WhippleParams())


def test_self_stable_at_5_and_falls_at_3(model):
    """Requirement: after a push the lean at 5 m/s decays under 10 % of its peak within
    10 s; at 3 m/s it grows (the bicycle falls)."""
    stable = st.push_response(None, 5.0, model=model)
    assert stable.time[-1] == pytest.approx(10.0)
    assert stable.final_ratio < 0.10 and math.isnan(stable.fallen_at)
    falls = st.push_response(None, 3.0, model=model)
    assert np.abs(falls.lean).max() > st.FALLEN and falls.fallen_at < 10.0


def test_linear_lean_matches_ode_integration():
    """The matrix-exponential response equals an adaptive ODE solution (rtol 1e-10) to
    1e-7 rad."""
    p = WhippleParams()
    times = np.arange(0.0, 5.0, 0.01)
    got = st.linear_lean(p, 5.0, times)
    a = wa.state_matrix(5.0, wa.matrices(p))
    sol = solve_ivp(lambda t, x: a @ x, (0, times[-1]), [0, 0, st.PUSH_LEAN_RATE, 0],
                    t_eval=times, rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(got, sol.y[0], atol=1e-7)


def test_late_ratio_of_a_known_decay():
    """φ = e^(−t/τ) sampled over 10 s: the last 2 s start at 8 s, ratio e^(−8/τ)."""
    t = np.arange(0.0, 10.001, 0.01)
    assert st.late_ratio(t, np.exp(-t / 4.0)) == pytest.approx(math.exp(-2.0), rel=1e-9)


def test_5_5_mps_uses_the_derived_bound():
    """At 5.5 m/s the linear benchmark itself stays above 10 % (its capsize eigenvalue
    needs ln 10 / |s| > 10 s), so the judged metric is the difference with the bound."""
    cap = wa.modes(5.5, wa.matrices(WhippleParams())).capsize
    assert math.log(10) / abs(cap) > 10.0
    run = st.push_response(None, 5.5)
    metrics = {m.name: m for m in st.stability_metrics(None, run)}
    judged = metrics["|lean ratio − linear benchmark's|"]
    assert judged.target.kind == "derived bound"
    lin = metrics["linear benchmark: lean over the last 2 s / peak"].value
    assert lin > 0.1 and judged.target.value == pytest.approx(lin * (math.exp(0.5) - 1))
    assert judged.value <= judged.target.value


def test_bad_push_raises(model):
    with pytest.raises(ValueError, match=r"lean_rate = 0.0 rad/s; valid range"):
        st.push_response(None, 5.0, lean_rate=0.0, model=model)


def test_the_drawn_push_strength_is_the_runs():
    """A push member's lean rate is its draw: the linear benchmark's lean is linear in
    the push, so its curve scales by the ratio of the pushes exactly (to rounding)."""
    import numpy as np

    from wmr_mujoco.robots.whipple import SPEC as WHIPPLE
    from wmr_mujoco.robots.whipple import stability as st

    s = WHIPPLE.scenario("push at 5 m/s")
    strong = s.member({st.PUSH: 1.2 * st.PUSH_LEAN_RATE})
    lin = {k: next(x for x in m.evaluate(m, None).series if x.label == "linear benchmark")
           for k, m in (("nominal", s), ("strong", strong))}
    np.testing.assert_allclose(lin["strong"].y[:50], 1.2 * lin["nominal"].y[:50], rtol=1e-9)


def test_push_response_samples_the_step_by_step_run(model):
    # The steps between samples run in C (mj_step with nstep): the same states as one
    # mj_step at a time, so the same sampled leans, to the bit (and the same fall time).
    import mujoco

    for speed in (3.0, 5.0):  # one that falls, one that recovers
        got = st.push_response(None, speed, model=model)
        data = mujoco.MjData(model)
        st.pushed_start(model, data, None, speed, st.PUSH_LEAN_RATE)
        dt = model.opt.timestep
        every = max(1, round(st.SAMPLE / dt))
        leans = []
        for k in range(round(st.PUSH_DURATION / dt) + 1):
            if k % every == 0:
                leans.append(st.lean_angle(data.qpos[3:7]))
                if abs(leans[-1]) > st.FALLEN:
                    break
            mujoco.mj_step(model, data)
        np.testing.assert_array_equal(got.lean, leans)
