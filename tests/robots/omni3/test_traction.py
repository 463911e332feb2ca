"""omni3's slip onset: one ramped run against the traction limit."""

import numpy as np
import pytest

from wmr_mujoco.models.params import SimParams
from wmr_mujoco.robots.omni3 import traction as tr
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.runs import hybrid

#: omni3 with the collision class's contact (contact bits) at the step and time constant it
#: had when these claims were derived (1 ms, 2 ms; docs/omni-dynamics.md). The default is
#: now the floor pairs' remedy (floor_impedance 0.001, 1.25 ms, solref 3.75 ms,
#: docs/floor-contact.md § 4), where the hybrid model's tolerances are not re-derived yet.
COLLISION_CLASS = OmniParams(floor_impedance=0.0,
                              sim=SimParams(timestep=0.001, contact_timeconst=0.002))


def test_slip_onset_follows_the_wheel_phase():
    """Issue 24: the measured onset spreads by ~20 % over the wheels' start phase. The
    hybrid model on the same ramp from the same start (loads at the contact points, with
    the heave: ``tests/robots/roller_wheels/test_omni_heave.py``) meets issue 16's 5 % at
    every phase of a pitch on a 5° grid, while the quasi-static μ N at rest (one number for all
    phases) misses it. The grid leaves out the two exactly symmetric starts (every wheel
    at a roller's centre, 0° and 30°), where the physics' slip re-sticks once and its
    reading jumps by ~12 % (an open point, docs/omni-dynamics.md). The ramp's derived
    resolution stays under 2 % of the onset (so 5 % is not decided by the reading)."""
    runs = tr.measure_slip_onsets(np.radians(np.arange(2.5, 60.0, 5.0)),
                                  params=COLLISION_CLASS)
    model = [abs(r.predicted - r.measured) / r.measured for r in runs]
    static = [abs(r.quasi_static - r.measured) / r.measured for r in runs]
    assert max(model) <= 0.05 < max(static)
    assert all(r.resolution < 0.02 * r.measured for r in runs)
    assert runs[0].slip.shape == (runs[0].scales.size, 3)


def test_members_read_their_phase():
    """A member of the slip family runs from its drawn phase: the wheels start there (the
    rate servo holds them while the robot settles, to within a degree)."""
    from wmr_mujoco.robots import omni3

    sc = omni3.SPEC.scenario("slip onset").member({"phase": 20.0})
    tr.prepare([np.radians(20.0)], None)
    res = tr.evaluate_slip(sc, None)
    assert not tr._READY
    m = {x.name: x for x in res.metrics}
    assert m["slip-onset torque: predicted vs physics"].target is tr.SLIP
    run = tr.measure_slip_onsets([np.radians(20.0)])[0]
    np.testing.assert_allclose(np.degrees(run.thetas[0]), 20.0, atol=1.0)
    assert m["slip-onset torque, physics"].value == pytest.approx(run.measured)


def test_prediction_is_the_traction_limit():
    """At the predicted scale the limiting wheel's traction equals μ N exactly (the two
    are affine in the scale), and every other wheel is below its limit."""
    hy = hybrid(None)
    pat = tr._pattern(tr.PATTERN)
    s = tr.predicted_slip_torque(hy, pat, hy.friction)
    force, load = tr.traction_and_load(hy, s * pat)
    margin = hy.friction * load - abs(force)
    assert min(margin) == pytest.approx(0.0, abs=1e-9)
    assert sorted(margin)[1] > 0


@pytest.mark.parametrize("pattern", [(0.0, 0.0, 0.0), (1.0, float("nan"), 0.0)])
def test_bad_pattern_is_rejected(pattern):
    with pytest.raises(ValueError, match="pattern"):
        tr.measure_slip_onset(pattern)
