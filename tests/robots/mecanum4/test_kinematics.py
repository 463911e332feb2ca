"""mecanum4's kinematic adapter and judge: closed forms, and short runs through the runner."""

import dataclasses
import math

import numpy as np
import pytest

from wmr_mujoco.models.params import SimParams
from wmr_mujoco.robots.mecanum4 import SPEC, kinematic_runs
from wmr_mujoco.robots.mecanum4.collider import realised_twist
from wmr_mujoco.robots.mecanum4.kinematics import MecanumKinematics, is_step
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.roller_wheels import pitch_averaged as pa
from wmr_mujoco.validation.runner import run_scenario

P = MecanumParams()
#: The collision class's contact in the roller pairs at the step it was designed for.
STIFF = dataclasses.replace(P, floor_impedance=0.0, sim=SimParams(timestep=0.004,
                                                                  contact_timeconst=0.008))
K = pa.mean_secant(math.pi / P.rollers_per_wheel)


def run(name):
    return next(s for s in kinematic_runs() if s.name == name)


def rows(result):
    return {(r.metric, r.unit): r for r in result.rows}


def test_controls_are_the_ideal_wheel_rates():
    # θ̇ = (1/R) [1, ∓1, ∓(a + w)] ν (docs/mecanum.md §3), here for ν = (0, 0, 1).
    k = (P.half_length + P.half_track) / P.wheel_radius
    np.testing.assert_allclose(MecanumKinematics(P).controls(np.array([0.0, 0.0, 1.0]),
                                                             np.zeros(6)),
                               [-k, k, -k, k], atol=1e-12)


def test_rhs_carries_both_models():
    # Sideways at heading 90°: the judged model moves at the colliders' mean speed
    # (robots.mecanum4.collider, tested in test_collider.py and against MuJoCo's rolling
    # radius in tests/robots/mecanum4/test_contact.py), the ideal one at v, both along
    # −X (Rot(90°) ŷ = −x̂).
    x = np.array([0.0, 0.0, math.pi / 2, 0.0, 0.0, math.pi / 2])
    d = MecanumKinematics(P).rhs(x, np.array([0.0, 0.3, 0.0]))
    v = realised_twist(P, np.array([0.0, 0.3, 0.0]))[1]
    np.testing.assert_allclose(d, [-v, 0.0, 0.0, -0.3, 0.0, 0.0], atol=1e-12)


def test_only_held_nonzero_commands_are_steps():
    assert is_step(run("translate 0° (step)")) and not is_step(run("translate 0° (ramp)"))


def _advance(x, start, pose):
    """Distance travelled (translations) or angle turned (rotation) from ``start`` on."""
    if pose == "heading":
        return x[-1, 2] - x[start, 2]
    return float(np.linalg.norm(x[-1, :2] - x[start, :2]))


@pytest.mark.parametrize(("name", "pose", "derived"), [
    ("translate 90° (ramp)", "position", 1 - 1 / K),
    # Along a diagonal FL and RR stay at rest (ideal constraint): 1 − 2/(1 + k).
    ("translate 45° (ramp)", "position", 1 - 2 / (1 + K)),
    ("rotate (ramp)", "heading", 1 - (P.half_length + P.half_track)
     / (P.half_length * K + P.half_track)),
])
def test_steady_shortfall_is_the_pitch_averaged_one(name, pose, derived):
    # Physics: at steady speed (t ≥ 1 s, ramp over) the chassis falls short of the ideal
    # model by the derived fraction (k = ⟨sec φ⟩, robots/roller_wheels/pitch_averaged.py). Tolerance
    # ±25 %: the hand-over impacts and the four wheels' different roller phases are not
    # in the averaged model. Run on the collision class's stiff contact (STIFF): the
    # default's soft floor pairs (docs/floor-contact.md) add a shortfall of their own
    # (rolling radius lost to the rest depth, creep of the softer friction rows) that
    # the averaged model of rigid rollers leaves out; the kinematic targets judge the sum.
    s = dataclasses.replace(run(name), duration=2.0)
    tr = run_scenario(SPEC, s, params=STIFF).trace.arrays()
    i = np.searchsorted(tr["time"], 1.0)
    moved = _advance(tr["sim"], i, pose)
    ideal = _advance(tr["analytic"][:, 3:], i, pose)
    assert 1 - moved / ideal == pytest.approx(derived, rel=0.25)


def test_step_run_is_judged_on_the_requirement_against_the_step_model():
    s = dataclasses.replace(run("translate 0° (step)"), duration=1.0)
    r = rows(run_scenario(SPEC, s))
    pos = r[("worst position error", "% of path")]
    assert pos.basis.startswith("requirement") and pos.target == pytest.approx(1.0)
    # The chassis cannot beat friction: against the instant step of the kinematics it
    # lags by at least the traction-limited part V T/2 (T = V / (μ g / √2)), 5 %
    # allowance for contact softness. The step model predicts that lag: its error is
    # below a quarter of it (the rest: the simulator's start-up, docs/mecanum.md §4).
    lag = 0.3 * 0.3 / (P.sim.friction * 9.81 / math.sqrt(2)) / 2
    path = r[("path length", "m")].value
    kin = r[("worst position error, kinematic model", "% of path")].value * path / 100
    assert kin >= 0.95 * lag
    assert r[("worst position error", "m")].value < 0.25 * lag


def test_a_ramped_runs_exact_step_is_what_rk4_on_its_rhs_approximates():
    # 2000 steps of 1.25 ms (the model's timestep) of a ramp to (0.2, 0.1, 0.5): each
    # pose follows a held body twist per step, which RK4 integrates with Simpson's rule
    # on cos/sin of the heading: error ≤ |ν| r⁴ Δt⁵ / 2880 ≈ 2e-19 m per step, far below
    # the round-off of 2000 additions (~1e-16 m each): 1e-12 m bounds the difference.
    from wmr_mujoco.analytic.integrate import rk4_step
    from wmr_mujoco.robots.mecanum4.kinematics import MecanumKinematics

    adapter = MecanumKinematics(MecanumParams())
    x = y = np.zeros(6)
    u = np.array([0.2, 0.1, 0.5])
    for k in range(2000):
        x = rk4_step(adapter.rhs, x, u * min(1.0, k / 500), 0.00125)
        y = adapter.exact_step(y, u * min(1.0, k / 500), 0.00125)
    np.testing.assert_allclose(y, x, rtol=0, atol=1e-12)
    assert np.linalg.norm(y[:2]) > 0.3  # it moved: the comparison is not of zeros


@pytest.mark.parametrize("name", ["translate 45° (step)", "rotate (step)",
                                  "translate+rotate (ramp)"])
def test_trajectory_is_the_schedule_step_after_step(name):
    """All steps at once = RK4 on rhs (a step run) or the exact arcs (a ramped run).

    Same arithmetic in the same order; 1e-13 relative allows NumPy's and libm's sin/cos
    to differ in the last bit on some CPUs (bit for bit on the reference machine).
    """
    import wmr_mujoco
    from wmr_mujoco.analytic.integrate import rk4_step
    from wmr_mujoco.validation.runner import make_adapter

    s = run(name).members(0, 1)[0]  # a drawn member: scaled speeds
    model = wmr_mujoco.load("mecanum4")
    adapter = make_adapter(SPEC, s, model)
    dt = model.opt.timestep
    inputs = s.inputs_on(round(s.duration / dt), dt)
    x = np.r_[0.1, -0.2, 0.3, 0.1, -0.2, 0.3, 0.1, -0.2, 0.3, 0.0][:len(adapter.state_names)]
    ref = [x]
    for u in inputs:
        x = (adapter.exact_step(x, u, dt) if adapter.exact_step is not None
             else rk4_step(adapter.rhs, x, u, dt))
        ref.append(x)
    np.testing.assert_allclose(adapter.trajectory(ref[0], inputs, dt), ref, rtol=1e-13,
                               atol=1e-13)


def test_trajectory_computes_each_distinct_input_once_with_its_own_floats():
    # A ramp (every row new), a hold (one row many times) and a 0.0 beside a -0.0 (told
    # apart by their bytes): the realised twists are those of row-by-row calls.
    kin = MecanumKinematics(MecanumParams())
    ramp = np.linspace(0.0, 1.0, 7)[:, None] * np.array([0.3, 0.1, 0.5])
    rows = np.concatenate([ramp, np.repeat(ramp[-1:], 5, axis=0),
                           [[0.2, 0.0, 0.0], [0.2, -0.0, 0.0]]])
    want = np.array([kin.realised(r) for r in rows])
    np.testing.assert_array_equal(kin._realised_rows(rows), want)
    assert kin._realised_rows(np.empty((0, 3))).shape == (0, 3)
