"""The timestep study's candidates: steps, the scaled contact and the kept stiffness."""

from __future__ import annotations

from fractions import Fraction

import mujoco
import numpy as np
import pytest

from wmr_mujoco.bench import timestep_candidates as tc
from wmr_mujoco.models.loading import load
from wmr_mujoco.robots import get_spec


def test_the_steps_are_those_that_divide_every_control_period():
    """1, 1.25, 2, 2.5 and 5 ms divide 20, 50 and 100 ms; 1.5 ms (20/1.5) and 4 ms (50/4)
    do not. Checked by exact rational arithmetic, independently of the module's rule."""
    in_ms = [Fraction(s).limit_denominator(100000) * 1000 for s in tc.STEPS]
    assert in_ms == [1, Fraction(5, 4), 2, Fraction(5, 2), 5]
    for period_ms in (20, 50, 100):
        assert all((period_ms / s).denominator == 1 for s in in_ms)


@pytest.mark.parametrize("robot", ["omni3", "diffdrive"])
def test_a_longer_step_keeps_the_contact_time_constant_in_steps(robot):
    """MuJoCo as the oracle: the compiled model's floor pairs at the longest step (5 ms)
    have the same ``t_c/Δt`` as at the default step (omni3 sets ``contact_timeconst``
    itself, diffdrive's pairs take it from the step), and the model runs at the new step."""
    spec = get_spec(robot)
    default = load(spec, spec.params_type())
    dt = tc.STEPS[-1]
    assert dt > default.opt.timestep
    longer = load(spec, tc.at_step(spec, dt).params)
    assert longer.opt.timestep == dt
    assert default.npair > 0 and longer.npair == default.npair
    steps = default.pair_solref[:, 0] / default.opt.timestep
    assert longer.pair_solref[:, 0] / dt == pytest.approx(steps, rel=1e-12)
    # ζ kept unless asked for
    assert longer.pair_solref[:, 1] == pytest.approx(default.pair_solref[:, 1])
    half = load(spec, tc.at_step(spec, dt, 0.5).params)
    assert half.pair_solref[:, 1] == pytest.approx(0.5)


def test_candidates_are_the_default_step_at_other_damping_ratios_then_longer_steps():
    spec = get_spec("omni3")  # default 1.25 ms
    own = spec.params_type().sim.floor_dampratio
    assert own not in (0.5, 1.0)
    cands = tc.candidates(spec, (0.5, 1.0, 0.5, own))
    assert [(c.timestep, c.dampratio) for c in cands] == [(0.00125, 0.5), (0.00125, 1.0)] + [
        (dt, z) for dt in (0.002, 0.0025, 0.005) for z in (own, 0.5, 1.0)]
    assert [(c.timestep, c.dampratio) for c in tc.candidates(spec)] == [
        (dt, own) for dt in (0.002, 0.0025, 0.005)]


def test_a_robot_without_parameters_is_refused_by_name():
    spec = get_spec("omni3")
    bare = type(spec).__new__(type(spec))
    object.__setattr__(bare, "name", "nameless")
    object.__setattr__(bare, "params_type", None)
    with pytest.raises(ValueError, match="'nameless' has no parameters"):
        tc.at_step(bare, 0.002)


def _normal_kb(model: mujoco.MjModel) -> tuple[float, float]:
    """MuJoCo's own stiffness K and damping B of the floor contacts' normal rows.

    ``efc_KBIP`` holds them per row as the solver uses them (``refsafe`` applied), read at
    the first step the robot, dropped from its initial pose, touches the floor (with the
    pairs' constant impedance they do not depend on the depth; a softly damped candidate
    may bounce off later)."""
    data = mujoco.MjData(model)
    for _ in range(round(0.3 / model.opt.timestep)):
        mujoco.mj_step(model, data)
        if data.ncon:
            break
    rows = [data.contact[i].efc_address for i in range(data.ncon)]
    assert rows, "the robot reaches the floor"
    kb = data.efc_KBIP[rows, :2]
    assert np.ptp(kb[:, 0]) <= 1e-9 * kb[0, 0] and np.ptp(kb[:, 1]) <= 1e-9 * kb[0, 1]
    return float(kb[0, 0]), float(kb[0, 1])


@pytest.mark.parametrize("robot", ["omni3", "mecanum4"])
def test_a_stiffness_kept_step_keeps_mujocos_stiffness_and_lowers_its_damping(robot):
    """MuJoCo as the oracle: at each longer step the contact rows' K (``1/(d ζ² t_c²)``)
    equals the default's to round-off, and B (``2/(d t_c)``) falls as ``t_c/t_c'`` with
    ``t_c'`` the builder's least ``steps · Δt`` at the new step (3 steps for these two,
    ``models.builders.common.SLIDING_STEPS``), never under MuJoCo's ``2 Δt``."""
    spec = get_spec(robot)
    base = spec.params_type()
    k0, b0 = _normal_kb(load(spec, base))
    tc0 = max(base.sim.contact_timeconst, 3 * base.sim.timestep)
    cands = tc.stiffness_candidates(spec)
    assert [c.timestep for c in cands] == [s for s in tc.STEPS if s > base.sim.timestep]
    for c in cands:
        assert c.stiffness_kept and c.params.sim.contact_timeconst == base.sim.contact_timeconst
        k, b = _normal_kb(load(spec, c.params))
        tc1 = max(base.sim.contact_timeconst, 3 * c.timestep)
        assert k == pytest.approx(k0, rel=1e-9)
        assert b == pytest.approx(b0 * tc0 / tc1, rel=1e-9)
        assert c.dampratio == pytest.approx(base.sim.floor_dampratio * tc0 / tc1, rel=1e-12)


def test_the_effective_time_constant_is_mujocos_floor_of_two_steps():
    """The disc's pairs keep their own 5 ms at a 5 ms step; MuJoCo runs them at 10 ms."""
    spec = get_spec("disc")
    base = spec.params_type()
    longer = tc.at_step_same_stiffness(spec, 0.005)
    assert load(spec, longer.params).pair_solref[0, 0] == pytest.approx(0.005)
    assert tc.pair_timeconst(spec, longer.params) == pytest.approx(0.01)
    assert longer.dampratio == pytest.approx(base.sim.floor_dampratio * 0.005 / 0.01)


def test_a_step_whose_kept_stiffness_needs_a_damping_ratio_under_the_least_is_refused():
    """omni3 at 12.5 ms: t_c' = 3 Δt = 37.5 ms, ζ' = 0.8 · 3.75/37.5 = 0.08 < 0.1."""
    with pytest.raises(tc.DampratioTooSmallError, match="ζ' = 0.08 is under"):
        tc.at_step_same_stiffness(get_spec("omni3"), 0.0125)


def test_a_robot_without_floor_pairs_is_refused_not_skipped(monkeypatch):
    monkeypatch.setattr(tc, "load", lambda spec, params: type(
        "M", (), {"pair_solref": np.zeros((0, 2))})())
    with pytest.raises(ValueError, match="time constants are"):
        tc.stiffness_candidates(get_spec("omni3"))
