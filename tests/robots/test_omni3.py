"""omni3's torque judge on a synthetic run with known errors."""

import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.models.params import OmniParams
from wmr_mujoco.robots import omni3
from wmr_mujoco.validation.metrics import Trace


@pytest.fixture(scope="module")
def adapter():
    scenario = omni3.SPEC.scenario("torque")
    return scenario, omni3.dynamic_adapter(scenario, load("omni3"), OmniParams())


def test_each_velocity_component_is_judged_on_its_own_peak(adapter):
    scenario, ad = adapter
    t = np.linspace(0.0, 2.0, 21)
    ana = np.zeros((21, 6))
    ana[:, 3], ana[:, 4], ana[:, 5] = 0.2 * t, -0.1 * t, 0.5 * t  # u, v, r ramps
    sim = ana.copy()
    sim[10, 3] += 0.004  # u off by 1 % of its peak 0.4 m/s mid-run, back by the end
    sim[:, 5] *= 1.02  # r 2 % high throughout
    trace = Trace(time=list(t), sim=list(sim), analytic=list(ana))
    v = {m.name: m for m in omni3.judge_torques(scenario, trace, ad, omni3.TARGETS)}
    assert v["worst u error"].value == pytest.approx(1.0)
    assert v["worst v error"].value == pytest.approx(0.0, abs=1e-12)
    assert v["worst r error"].value == pytest.approx(2.0)
    assert v["final u: MuJoCo / Lagrange"].value == pytest.approx(1.0)
    traction = v["largest traction / μN"]
    assert traction.target is not None and traction.target.kind == "derived bound"
    assert 0 < traction.value < 1  # the scenario's torques stay below the traction limit
