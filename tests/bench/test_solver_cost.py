"""The solver-cost study: its settings, the two routes to a setting, timers and verdicts."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from wmr_mujoco.bench import solver_cost, solver_fidelity
from wmr_mujoco.bench.default_speed import Rounds, prepare_timed
from wmr_mujoco.bench.solver_cost import DEFAULT, SETTINGS, Setting
from wmr_mujoco.bench.solver_profile import run_drive
from wmr_mujoco.models.loading import load
from wmr_mujoco.robots import get_spec
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.omni3.params import OmniParams

OPT_FIELDS = ("solver", "jacobian", "cone", "iterations", "tolerance", "ls_iterations",
              "ls_tolerance", "disableflags")


@pytest.mark.parametrize("robot", ["omni3", "mecanum4"])
@pytest.mark.parametrize("setting", [s for s in SETTINGS if s.params], ids=lambda s: s.label)
def test_a_setting_as_parameters_builds_the_model_the_option_route_times(robot, setting):
    """The validated route (parameters -> builder) and the timed route (options set on the
    compiled default model) give the same options: what is timed is what is validated."""
    spec = get_spec(robot)
    built = load(spec, setting.robot_params(spec))
    timed = load(spec)
    setting.apply(timed)
    for name in OPT_FIELDS:
        assert getattr(built.opt, name) == getattr(timed.opt, name), name


def test_the_reduced_robot_expresses_only_the_solver_as_parameters():
    """omni3_reduced inherits the fields but its builder writes only ``solver`` (the rest
    are UNUSED): no validation of a setting its model would not carry, and each solver
    setting's parameters build a model that runs that solver."""
    spec = get_spec("omni3_reduced")
    expressed = {s.label: s.robot_params(spec) for s in SETTINGS
                 if s.robot_params(spec) is not None}
    assert set(expressed) == {"Newton", "CG", "PGS"}
    for label, params in expressed.items():
        assert load(spec, params).opt.solver == getattr(mujoco.mjtSolver, f"mjSOL_{label.upper()}")


def test_apply_adds_a_disable_flag_to_the_models_own():
    model = load(get_spec("omni3_reduced"))
    model.opt.disableflags = int(mujoco.mjtDisableBit.mjDSBL_WARMSTART)
    Setting("x", (("disableflags", mujoco.mjtDisableBit.mjDSBL_ISLAND),)).apply(model)
    assert model.opt.disableflags == (mujoco.mjtDisableBit.mjDSBL_WARMSTART
                                      | mujoco.mjtDisableBit.mjDSBL_ISLAND)


@pytest.mark.parametrize("cls", [OmniParams, MecanumParams])
@pytest.mark.parametrize("field", ["solver", "jacobian", "cone"])
def test_a_bad_choice_is_named_with_the_valid_ones(cls, field):
    with pytest.raises(ValueError, match=rf"{cls.__name__}\.{field} = 'bogus'; valid values"):
        cls(**{field: "bogus"})


def test_sparse_and_dense_jacobians_give_the_same_motion():
    """Jacobian storage is not physics: omni3 driven 0.25 s from its settled state with
    each. Newton stops when the relative improvement is below 1e-8; the two storages
    differ by the summation order only (round-off, ~1e-16 relative), which can at most
    flip one stop decision, changing qacc by the last Newton step's size (< 1e-6 m/s² at
    this tolerance), i.e. < 1e-9 m/s a step at 1.25 ms; over 200 steps < 2e-7 m/s:
    1e-7 m/s asserted on the platform's velocity (its speeds are ~0.1 m/s)."""
    spec = get_spec("omni3")
    runs = []
    for jac in (mujoco.mjtJacobian.mjJAC_DENSE, mujoco.mjtJacobian.mjJAC_SPARSE):
        t = prepare_timed(spec, None, 0.25)
        t.model.opt.jacobian = jac
        run_drive(t)
        runs.append(t.data.qvel[:6].copy())
    assert np.abs(runs[0] - runs[1]).max() < 1e-7
    assert np.abs(runs[0][:2]).max() > 1e-2  # the platform moved: not a trivial agreement


def test_costs_are_consistent_and_the_default_is_its_own_unit():
    """µs per step × real-time factor = the timestep in µs (both from the same median
    wall time), and the default's ratio is 1."""
    spec = get_spec("omni3_reduced")
    cs = solver_cost.costs(spec, (DEFAULT, _setting("jacobian sparse")), Rounds(0.2, 1))
    dt_us = load(spec).opt.timestep * 1e6
    assert cs[0].ratio == 1.0
    for c in cs:
        assert c.us_per_step * c.rtf == pytest.approx(dt_us, rel=1e-9)


def test_a_setting_that_throws_the_robot_off_the_floor_is_no_candidate():
    """The pyramidal cone at omni3's floor-pair impratio (1e4) launches the platform: its
    drive averages almost no contacts (the default: about 3 rollers touch), so its low
    cost is flagged, never offered as a candidate."""
    spec = get_spec("omni3")
    pyramidal = next(s for s in SETTINGS if s.label == "pyramidal")
    base, pyr = solver_cost.costs(spec, (DEFAULT, pyramidal), Rounds(0.3, 1))
    assert base.contacts > 2.0 and not base.error
    assert "left the floor" in pyr.error and not pyr.candidate


def test_only_cheaper_expressible_settings_are_validated():
    """A setting within the timing noise is no candidate, and one the parameters cannot
    express is not run through the validation (nothing is run here)."""
    spec = get_spec("omni3")
    timed_only = Setting("tolerance", (("tolerance", 1e-4),))
    sparse = _setting("jacobian sparse")
    assert solver_fidelity.judge_settings(spec, [timed_only], [0]) == {}
    assert solver_cost.Cost(50.0, 20.0, 0.95, 3.0).candidate is False
    assert solver_cost.Cost(50.0, 20.0, 0.5, 3.0).candidate is True
    assert sparse.robot_params(spec) == OmniParams(jacobian="sparse")


def test_bad_robot_or_seed_fails_before_any_work(capsys):
    with pytest.raises(ValueError, match="nosuchrobot"):
        solver_cost.main(["nosuchrobot"])
    with pytest.raises(SystemExit, match="--seeds: -1"):
        solver_cost.main(["omni3", "--seeds", "-1"])
    assert capsys.readouterr().out == ""


def _setting(label):
    return next(s for s in SETTINGS if s.label == label)


def test_omni3_defaults_to_the_sparse_jacobian_the_study_validated():
    """The shipped file carries the default (MuJoCo alone would pick dense below 60 DoF)."""
    assert load(get_spec("omni3")).opt.jacobian == mujoco.mjtJacobian.mjJAC_SPARSE
    assert _setting(solver_cost.PREVIOUS["omni3"]).robot_params(get_spec("omni3")) == \
        OmniParams(jacobian="auto")


def test_a_setting_equal_to_the_default_is_not_timed_against_it():
    """mecanum4 has 74 DoF: MuJoCo's ``auto`` already picks the sparse Jacobian there, so
    both settings are its defaults, not candidates (a noisy ratio cannot make them one)."""
    spec = get_spec("mecanum4")
    assert load(spec).nv >= 60  # MuJoCo's rule: auto is sparse from 60 DoF
    costs = solver_cost.costs(spec, (DEFAULT, _setting("jacobian auto"),
                                     _setting("jacobian sparse")), Rounds(0.1, 1))
    assert all("default's own options" in c.error and not c.candidate for c in costs[1:])
