"""omni3's physics batches from several starts."""

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.params import SimParams
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.physics import WHEELS, rollout_from, settle_at_phases
from wmr_mujoco.robots.omni3.runs import SETTLE, base_states, settled
from wmr_mujoco.sim.engine import STATE_SPEC, simulate

#: omni3 with the collision class's contact (contact bits) at the step and time constant it
#: had when these claims were derived (1 ms, 2 ms; docs/omni-dynamics.md). The default is
#: now the floor pairs' remedy (floor_impedance 0.001, 1.25 ms, solref 3.75 ms,
#: docs/floor-contact.md § 4), where the hybrid model's tolerances are not re-derived yet.
COLLISION_CLASS = OmniParams(floor_impedance=0.0,
                              sim=SimParams(timestep=0.001, contact_timeconst=0.002))


def test_settled_at_each_phase_and_rolled_out_as_the_loop_would():
    """Each start has every wheel at its phase (the servo holds them, within a degree of
    creep under the weight's moment) and the robot at rest (below a hundredth of the
    scenarios' 0.3 m/s and 1 rad/s: the held wheels still creep); a batch run from a start is
    the Python loop's run from the same state, to rounding (the solver's warm start is
    not part of the state: 1e-9 of a state of order 1)."""
    model, _ = settled(ActuationMode.RATE, COLLISION_CLASS)
    phases = [0.0, math.radians(15.0), math.radians(47.0)]
    starts = settle_at_phases(model, WHEELS, phases, SETTLE)
    _, twist, th, rates = base_states(model, starts)
    np.testing.assert_allclose(th, np.tile(np.array(phases)[:, None], 3), atol=math.radians(1))
    assert np.abs(twist).max() < 3e-3 and np.abs(rates).max() < 1e-2
    controls = np.tile([2.0, -1.0, 0.5], (200, 1))
    batch = rollout_from(model, starts[1:2], [controls])[0]
    data = mujoco.MjData(model)
    mujoco.mj_setState(model, data, starts[1], STATE_SPEC)
    mujoco.mj_forward(model, data)
    np.testing.assert_allclose(batch[-1], simulate(model, data, controls)[-1], atol=1e-6)


def test_rollout_needs_one_start_per_sequence():
    model, _ = settled(ActuationMode.RATE, COLLISION_CLASS)
    with pytest.raises(ValueError, match="one start per"):
        rollout_from(model, np.zeros((2, 5)), [np.zeros((3, 3))])


def test_contact_wheels_names_the_wheel_of_each_floor_contact():
    """Resting on its three wheels, each floor contact is a roller of one of them (the
    roller body's parent is that wheel), every wheel has one, and no contact is assigned
    that is not a floor contact: checked contact by contact against the model's bodies."""
    from wmr_mujoco.robots.omni3.physics import contact_wheels

    model, _ = settled(ActuationMode.RATE, None)
    start = settle_at_phases(model, WHEELS, [math.radians(10.0)], SETTLE)[0]
    data = mujoco.MjData(model)
    mujoco.mj_setState(model, data, start, STATE_SPEC)
    mujoco.mj_fwdPosition(model, data)
    got = contact_wheels(model, data)
    floor = model.geom("floor").id
    wheel_ids = [model.body(w).id for w in WHEELS]
    assert got.shape == (data.ncon,) and set(got[got >= 0]) == {0, 1, 2}
    for c, wheel in zip(data.contact[:data.ncon], got, strict=True):
        if floor not in (c.geom1, c.geom2):
            assert wheel == -1
            continue
        geom = c.geom2 if c.geom1 == floor else c.geom1
        assert wheel >= 0 and wheel_ids[wheel] == model.body_parentid[model.geom_bodyid[geom]]
