"""omni3's step commands and torque inputs: physics against the predicting models."""

import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.models.actuation import ActuationMode
from wmr_mujoco.models.params import SimParams
from wmr_mujoco.robots import omni3
from wmr_mujoco.robots.omni3 import DYNAMIC_SPECS
from wmr_mujoco.robots.omni3 import dynamics as dy
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.omni3.runs import (
    CONTACT_WINDOW,
    RunSpec,
    cached_runs,
    hybrid,
    settled,
    simulate_runs,
    wheels_off_floor,
)
from wmr_mujoco.robots.roller_wheels.twist_errors import twist_metrics
from wmr_mujoco.sim.engine import STATE_SPEC

#: omni3 with the collision class's contact (contact bits) at the step and time constant it
#: had when these claims were derived (1 ms, 2 ms; docs/omni-dynamics.md). The default is
#: now the floor pairs' remedy (floor_impedance 0.001, 1.25 ms, solref 3.75 ms,
#: docs/floor-contact.md § 4), where the hybrid model's tolerances are not re-derived yet.
COLLISION_CLASS = OmniParams(floor_impedance=0.0,
                              sim=SimParams(timestep=0.001, contact_timeconst=0.002))


def _metrics(name, evaluate, params=None):
    res = evaluate(omni3.SPEC.scenario(name), params)
    return {m.name: m for m in res.metrics}, res.series


def test_step_command_hybrid_beats_kinematics():
    """Step to 0.3 m/s along x: the servo saturates at its torque limit, so the kinematic
    prediction runs ahead; the hybrid model with the servo law meets issue 16's 0.3 % of
    path and 0.2°, and is at least three times closer than the kinematics."""
    m, series = _metrics("step 0°", dy.evaluate_step)
    hybrid = m["hybrid: worst position error"]
    assert hybrid.target is dy.STEP_PATH and hybrid.value <= 0.3
    assert m["hybrid: worst heading error"].value <= 0.2
    assert m["kinematic: worst position error"].value > 3 * hybrid.value
    assert {s.label for s in series} >= {"physics", "kinematic", "hybrid"}


def test_torque_rows_declared():
    """Every twist component and the pose carry issue 16's requirements, open over their
    families (issue 24: shown with their figures, not judged; the spread is the family
    table's, ``python -m wmr_mujoco.bench.omni_families``); under pure rotation, where the
    premise of the one-sample allowance holds (the model's wheel phase within one step's
    turn of the physics'), the twist is compared with jumps one sample apart and the
    same-instant figure reported beside; the Lagrange model's rows and the old
    single-instant figure are reported only."""
    # The premise (wheel phase within a step's turn) is derived for the collision class.
    m, _ = _metrics("torque along x", dy.evaluate_torque, COLLISION_CLASS)
    for c in "uvr":
        row = m[f"hybrid: worst {c} error"]
        assert row.target is dy.TORQUE_COMPONENT and not row.target.judged
    pose = m["hybrid: worst position error"]
    assert pose.target is dy.TORQUE_PATH and not pose.target.judged
    assert m["Lagrange: |Δν| / |ν| at the last instant"].target is None
    assert m["Lagrange: worst u error"].target is None
    rot, _ = _metrics("torque rotate", dy.evaluate_torque, COLLISION_CLASS)
    for c in "uvr":
        assert rot[f"hybrid: worst {c} error"].target is dy.TORQUE_COMPONENT
        assert rot[f"hybrid: worst {c} error, sample by sample"].target is None
    assert abs(rot["hybrid: worst wheel phase"].value) <= 1.0


def test_a_hand_over_jump_lands_on_the_model_sample_or_the_next():
    """The derivation of EVENT_SHIFT (docs/omni-dynamics.md § 10): MuJoCo finds a contact
    at the positions that start a step and its impulse ends that step's velocity, so the
    physics' yaw-rate jump under pure rotation (each over 1 % of the peak: all three wheels
    switch together) lands on the hybrid model's sample of the same jump or on the next
    one, never earlier and never two apart; and the jumps alternate in sign (the lever
    L + e, L − e, L + e, ...) in both."""
    # Derived for the collision class's contact detection and impulse (see COLLISION_CLASS).
    run = cached_runs(DYNAMIC_SPECS, COLLISION_CLASS)["torque rotate"]
    r, rh = run.twist[:, 2], run.hybrid.twist[:, 2]
    level = 0.01 * np.abs(r).max()
    phys = np.flatnonzero(np.abs(np.diff(r)) > level)
    model = np.flatnonzero(np.abs(np.diff(rh)) > level)
    assert len(phys) == len(model) >= 10
    assert set((phys - model).tolist()) <= {0, 1}
    assert np.all(np.sign(np.diff(r)[phys]) == np.sign(np.diff(rh)[model]))
    assert np.all(np.diff(np.sign(np.diff(r)[phys])) != 0)


def test_kinematic_pose_of_a_steady_turn_is_a_circle():
    """Constant (u, 0, r): the exact path is the arc (ρ sin rt, ρ (1 − cos rt), rt) with
    ρ = u/r; the midpoint rule's error over 2 s at 4 ms is ~ρ (r Δt)² t / 24 < 1e-6 m."""
    dt, n, u, r = 0.004, 500, 0.3, 1.0
    pose = dy.kinematic_pose(np.tile([u, 0.0, r], (n + 1, 1)), dt)
    t = np.arange(n + 1) * dt
    exact = np.column_stack([u / r * np.sin(r * t), u / r * (1 - np.cos(r * t)), r * t])
    np.testing.assert_allclose(pose, exact, atol=1e-6)


def test_path_of_a_pure_rotation_is_the_wheel_arc():
    """Turning in place through ψ: the path is L ψ (the arc of the wheel centres)."""
    pose = np.column_stack([np.zeros(11), np.zeros(11), np.linspace(0.0, 2.0, 11)])
    assert dy.path_length(pose, 0.15) == pytest.approx(0.3)


@pytest.mark.parametrize("kwargs, match", [
    ({"command": (0.3, math.nan, 0.0)}, "command"),
    ({"duration": -1.0}, "duration"),
    ({"lead_in": (math.inf, 0.0, 0.0)}, "lead_in"),
])
def test_bad_run_is_rejected(kwargs, match):
    args = {"name": "x", "mode": ActuationMode.RATE, "command": (1.0, 1.0, 1.0),
            "duration": 1.0, **kwargs}
    with pytest.raises(ValueError, match=match):
        RunSpec(**args)


def test_torque_plots_show_each_twist_component_of_physics_and_models():
    """A torque run's figure: one panel per body-twist component (what is judged), each
    with the physics and the three predictions; the series are the run's own arrays."""
    _, series = _metrics("torque rotate", dy.evaluate_torque)
    panels = {}
    for s in series:
        panels.setdefault(s.ylabel, set()).add(s.label)
    assert list(panels) == ["u [m/s]", "v [m/s]", "r [rad/s]"]
    assert all(p == {"physics", "kinematic", "Lagrange", "hybrid"} for p in panels.values())
    run = cached_runs(DYNAMIC_SPECS)["torque rotate"]
    phys_r = next(s for s in series if s.ylabel == "r [rad/s]" and s.label == "physics")
    assert np.array_equal(phys_r.y, run.twist[:, 2])
    hyb_r = next(s for s in series if s.ylabel == "r [rad/s]" and s.label == "hybrid")
    assert np.array_equal(hyb_r.y, run.hybrid.twist[:, 2])


def test_soft_hand_overs_follow_the_physics_at_half_the_step():
    """At half the shipped step the soft contact spreads each hand-over's jump over a few
    steps (ρ = 1 − Δt d_f b ≈ ½, sim/soft_contact.py). Pure rotation's yaw rate, jumps
    one sample apart: the hybrid model with that relaxation stays within issue 16's 1 %
    of peak, the same model making each hand-over at once misses it by more than twice
    (the spread jump differs from the instant one by about half a jump, several % of peak,
    for a sample or two)."""
    spec = next(s for s in dy.TORQUE_SPECS if s.name == "torque rotate")
    # ρ ≈ ½ at half the step is the collision class's (at 1 ms, COLLISION_CLASS).
    step = COLLISION_CLASS.sim.timestep / 2

    def worst_r(relax: bool) -> float:
        run = simulate_runs([spec], COLLISION_CLASS, timestep=step, relax=relax)[spec.name]
        rows = {m.name: m.value for m in twist_metrics(
            "h", run.twist, run.hybrid.twist, hybrid(COLLISION_CLASS).distance,
            shift=dy.EVENT_SHIFT)}
        return rows["h: worst r error"]

    assert worst_r(True) <= 1.0 < 2.0 < worst_r(False)


def test_wheels_off_floor_reads_the_contacts_of_each_state():
    """The settled robot has every wheel on the floor; raised 1 cm (free joint z), none;
    tilted about the axis of wheel 1 so that wheel 1 rises, wheel 1 alone is off."""
    model, data = settled(ActuationMode.TORQUE)
    rest = np.empty(mujoco.mj_stateSize(model, STATE_SPEC))
    mujoco.mj_getState(model, data, rest, STATE_SPEC)
    raised = rest.copy()
    raised[1 + 2] += 0.01  # time first, then qpos: free joint (x, y, z, quaternion)
    # Tilt 0.1 rad about the horizontal axis normal to wheel 1's direction (through the
    # centre): wheel 1 rises by L sin 0.1 ≈ 15 mm, wheels 2 and 3 sink by half that.
    alpha = float(hybrid().wheel_angles[0])
    axis = np.array([-np.sin(alpha), np.cos(alpha), 0.0])
    tilt = np.zeros(4)
    mujoco.mju_axisAngle2Quat(tilt, axis, -0.1)
    tilted = rest.copy()
    quat = np.zeros(4)
    mujoco.mju_mulQuat(quat, tilt, rest[1 + 3:1 + 7])
    tilted[1 + 3:1 + 7] = quat
    off = wheels_off_floor(model, np.array([rest, raised, tilted]))
    assert not off[0].any() and off[1].all()
    assert off[2].tolist() == [True, False, False]


def test_off_floor_metric_is_reported_and_zero_under_torque():
    """Reported only; the torque inputs stay below the traction limit, so no wheel lifts."""
    m, _ = _metrics("torque along y", dy.evaluate_torque)
    row = m[f"wheels off the floor, first {CONTACT_WINDOW:g} s"]
    assert row.target is None and row.value == 0.0
