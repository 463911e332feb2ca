"""The warp backend's refusals, before any stepping, and its report of a divergence."""

from dataclasses import replace

import mujoco
import pytest

import wmr_mujoco as wmr
from wmr_mujoco.batch.warp_backend import WarpBackend

pytestmark = pytest.mark.extra  # MuJoCo Warp (the gpu extra)


def test_pgs_solver_is_refused_with_the_nearest_setting():
    model = wmr.load("diffdrive")
    model.opt.solver = mujoco.mjtSolver.mjSOL_PGS
    with pytest.raises(ValueError, match=r"solver is PGS.*Newton or CG.*backend='rollout'"):
        WarpBackend().check("diffdrive", [model])


def test_a_field_warp_cannot_batch_is_named():
    """Rolling friction on the caster changes its contact dimension (condim 3 -> 6), a
    field MuJoCo Warp shares across worlds: refused for members, naming it."""
    base = wmr.get_spec("diffdrive").params_type()
    rolling = replace(base, caster=replace(base.caster, rolling_friction=True))
    with pytest.raises(ValueError, match=r"cannot vary 'geom_condim'"):
        wmr.simulate_batch("diffdrive", [[0.5, 0.0]] * 2, 0.1, [base, rolling], backend="warp")


def test_bad_devices():
    with pytest.raises(ValueError, match="non-empty list of Warp device names"):
        WarpBackend(devices="cpu")
    with pytest.raises(ValueError, match=r"probe_steps = -1; give an integer >= 0"):
        WarpBackend(probe_steps=-1)
    with pytest.raises(ValueError, match=r"graph = 'yes'; give True or False"):
        WarpBackend(graph="yes")


def test_a_divergence_is_reported_naming_float32_and_rollout():
    """The ball caster on contact bits under the floor pairs' impratio (the model before
    its pair, bench.caster_conditioning): MuJoCo Warp's float32 Newton step goes
    non-finite within the first second of driving straight (C MuJoCo runs it). Reported,
    never returned, with the reason and the backend that runs it."""
    from wmr_mujoco.bench.caster_conditioning import variants
    from wmr_mujoco.robots import get_spec
    from wmr_mujoco.sim.stepping import SimulationDivergedError
    from wmr_mujoco.validation.runner import prepare

    spec = get_spec("diffdrive")
    straight = next(s for s in spec.scenarios if s.name == "straight")
    prep = prepare(spec, straight, None, model=variants("diffdrive")["contact bits"])
    prep.controls = prep.controls[:500]
    with pytest.raises(SimulationDivergedError, match=r"non-finite .*float32.*'rollout'"):
        WarpBackend().run([prep])
