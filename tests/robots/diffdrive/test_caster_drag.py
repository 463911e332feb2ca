"""The ball caster rolls freely in every direction; with rolling friction it drags μ_r N/r."""

import copy
import dataclasses

import mujoco
import numpy as np
import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.robots.diffdrive import analytic as diffdrive
from wmr_mujoco.robots.diffdrive import caster_drag
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams

P = DiffDriveParams()
ROLLING = dataclasses.replace(P, caster=dataclasses.replace(P.caster, rolling_friction=True))
GRAVITY = 9.81
#: A rolling-resistance coefficient of 1e-4 (hard ball on hard floor is ~1e-3) on the
#: ball's ≈ 16 N load would be 1.6e-3 N. The default model has no rolling resistance
#: (condim 3, frictionless joint), so the contact force must stay far below that: 1e-4 N.
DRAG_BOUND = 1e-4


def _drive(model, v, omega, seconds, record=None):
    """Ramp to (v, ω) over ``RAMP`` after ``SETTLE`` at rest; optionally record each step."""
    data = mujoco.MjData(model)
    target = np.array(diffdrive.wheel_speeds(v, omega, P.track)) / P.wheel.radius
    dt = model.opt.timestep
    for k in range(round(seconds / dt)):
        data.ctrl[:] = np.clip((k * dt - caster_drag.SETTLE) / caster_drag.RAMP, 0, 1) * target
        mujoco.mj_step(model, data)
        if record is not None:
            record(k * dt, data)
    return data


def test_freely_rolling_drag_is_negligible_straight_and_spinning():
    model = load("diffdrive")
    for _, v, omega in caster_drag.MANOEUVRES:
        rec = caster_drag.steady_drag(model, P, v, omega)
        assert abs(np.mean(rec.drag)) < DRAG_BOUND
        assert np.max(np.abs(rec.drag)) < DRAG_BOUND
        assert np.all(rec.predicted == 0.0)  # condim 3: no rolling-friction prediction


@pytest.mark.parametrize("v,omega", [(0.5, 0.0), (0.0, 1.5), (-0.3, 0.8)])
def test_ball_rolls_without_slip_in_each_direction(v, omega):
    # Forward, sideways (the caster moves across the chassis when spinning in place) and
    # backwards-diagonal: the ball's contact point must be at rest, v_c + ω × (−r ẑ) = 0.
    model = load("diffdrive")
    data = _drive(model, v, omega, caster_drag.SETTLE + caster_drag.RAMP + 0.3)
    vel = np.zeros(6)
    mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_BODY, model.body("caster").id,
                             vel, 0)
    w, vc = vel[:3], vel[3:]
    contact_velocity = vc + np.cross(w, [0.0, 0.0, -P.caster.radius])
    # A locked or dragging ball would slide at 100 % of its centre's speed; a rolling one
    # only creeps in its soft contact (rolling radius r − δ/2 with δ ≈ 8 µm gives
    # ω δ/2 ≈ 0.06 mm/s at 0.3 m/s; about 0.5 mm/s measured in turns). Bound: 1 %.
    speed = np.linalg.norm(vc[:2])
    assert speed > 0.2  # it did move
    assert np.linalg.norm(contact_velocity[:2]) < 0.01 * speed


def test_accelerating_ball_carries_its_rolling_inertia_force():
    # Euler for the ball, step by step: its only moment about its centre is the floor
    # force's (frictionless ball joint, weight and socket force through the centre,
    # condim 3: no contact torque), and a sphere has no gyroscopic term, so
    # (p − x_c) × F = I α exactly in MuJoCo's own dynamics; tolerance: the solver's
    # residual, 1e-6 of the moment's scale.
    # Then the drag's size: rolling without slip, f = (I/r²) a_c = (2/5) m_c a_c against the
    # motion on the speed ramp (a ≈ 0.5 m/s / RAMP), a_c the ball centre's mean
    # acceleration over the window T. Euler makes the mean force (I/r) Δω/T exactly, so
    # the bound is the creep s = v_c − r ω: it stays below 1 % of the speed (test above),
    # so |Δs| / Δv_c ≤ 2 · 0.01 · v_max / (a T) = 2 · 0.01 · 0.5 / 0.35 ≈ 2.9 %: 3 %.
    model = load("diffdrive")
    ball = model.body("caster").id
    geom = model.geom("caster_collision").id
    inertia = 0.4 * P.caster.mass * P.caster.radius ** 2
    rows = []
    lo, hi = caster_drag.SETTLE + 0.1, caster_drag.SETTLE + caster_drag.RAMP - 0.05

    def record(t, live):
        if not lo < t < hi:
            return
        data = copy.copy(live)
        mujoco.mj_forward(model, data)
        mujoco.mj_rnePostConstraint(model, data)
        (i,) = [k for k in range(data.ncon) if geom in data.contact[k].geom]
        c = data.contact[i]
        f = np.zeros(6)
        mujoco.mj_contactForce(model, data, i, f)
        sign = 1.0 if c.geom[1] == geom else -1.0
        force = sign * (f[:3] @ c.frame.reshape(3, 3))
        moment = np.cross(c.pos - data.xpos[ball], force)
        alpha = data.cacc[ball][:3]
        np.testing.assert_allclose(moment, inertia * alpha,
                                   atol=1e-6 * np.abs(inertia * alpha).max() + 1e-12)
        vel = np.zeros(6)
        mujoco.mj_objectVelocity(model, live, mujoco.mjtObj.mjOBJ_BODY, ball, vel, 0)
        rows.append((t, caster_drag.caster_forces(model, live)[0], vel[3]))

    _drive(model, 0.5, 0.0, caster_drag.SETTLE + caster_drag.RAMP, record)
    assert len(rows) > 50
    t, force, speed = np.asarray(rows).T
    accel = (speed[-1] - speed[0]) / (t[-1] - t[0])  # the ball centre's mean acceleration
    force = float(np.mean(force[1:]))
    assert accel > 0.5 * 0.5 / caster_drag.RAMP  # it is on the ramp (the servo lags a little)
    assert force == pytest.approx(0.4 * P.caster.mass * accel, rel=0.03)


def test_rolling_friction_drag_is_mu_r_times_the_static_load_over_r():
    # Independent of the contact solver: the ball's load from the moment balance about
    # the axle at rest, N_c = M g x_com / x_c (CoM and caster behind the axle), and μ_r
    # the larger third friction coefficient of ball and floor (MuJoCo's default mixing).
    # Drag μ_r N_c / r_c. 3 %: one partial contact-chatter cycle in the window (≤ 1.3 %,
    # caster_drag.ROLLING_DRAG_REL), the drive torque's and the drag's pitch moments on
    # N_c (≈ F h / x_c with h ≈ R: ≈ 0.5 %), the cone correction (μ_r/μ r_c)² ≈ 3e-5.
    model = load("diffdrive", ROLLING)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    chassis = model.body("chassis").id
    x_com = data.subtree_com[chassis][0] - data.xpos[chassis][0]
    x_c = data.xpos[model.body("caster").id][0] - data.xpos[chassis][0]
    load_c = P.total_mass * GRAVITY * x_com / x_c
    ball, floor = model.geom("caster_collision").id, model.geom("floor").id
    mu_r = max(model.geom_friction[ball][2], model.geom_friction[floor][2])
    rec = caster_drag.steady_drag(model, ROLLING, 0.5, 0.0)
    assert np.mean(rec.drag) == pytest.approx(mu_r * load_c / P.caster.radius, rel=0.03)


def test_measurement_scenario_reports_and_judges():
    from wmr_mujoco.robots.diffdrive import SPEC

    result = caster_drag.evaluate(SPEC.scenario("caster drag"), None)
    judged = [m for m in result.metrics if m.target is not None]
    assert len(judged) == 1 and abs(judged[0].value) <= judged[0].target.value
    assert {s.label for s in result.series} >= {"drag, straight, condim 3",
                                                "drag, straight, condim 6"}
