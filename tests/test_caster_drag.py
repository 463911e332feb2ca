"""The ball caster rolls freely in every direction and adds no measurable drag."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco import caster_drag
from wmr_mujoco.params_wheeled import DiffDriveParams

P = DiffDriveParams()
#: A rolling-resistance coefficient of 1e-4 (hard ball on hard floor is ~1e-3) on the
#: ball's ≈ 16 N load would be 1.6e-3 N. The model has no rolling resistance (condim 3,
#: frictionless joint), so the contact force must stay far below that: 1e-4 N.
DRAG_BOUND = 1e-4


def test_contact_drag_is_negligible_straight_and_spinning():
    figs = caster_drag.contact_drag(P, (("straight", 0.5, 0.0), ("spin", 0.0, 1.5)))
    for f in figs:
        assert abs(f.mean) < DRAG_BOUND, f
        assert f.worst < DRAG_BOUND, f


@pytest.mark.parametrize("v,omega", [(0.5, 0.0), (0.0, 1.5), (-0.3, 0.8)])
def test_ball_rolls_without_slip_in_each_direction(v, omega):
    # Forward, sideways (the caster moves across the chassis when spinning in place) and
    # backwards-diagonal: the ball's contact point must be at rest, v_c + ω × (−r ẑ) = 0.
    model = caster_drag._model(P)
    data = caster_drag._run(model, P, v, omega, caster_drag.SETTLE + caster_drag.RAMP + 0.5)
    ball = model.body("caster").id
    vel = np.zeros(6)
    mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_BODY, ball, vel, 0)
    w, vc = vel[:3], vel[3:]
    contact_velocity = vc + np.cross(w, [0.0, 0.0, -P.caster.radius])
    # A locked or dragging ball would slide at 100 % of its centre's speed; a rolling one
    # only creeps in its soft contact (rolling radius r − δ/2 with δ ≈ 8 µm gives
    # ω δ/2 ≈ 0.06 mm/s at 0.3 m/s; about 0.5 mm/s measured in turns). Bound: 1 %.
    speed = np.linalg.norm(vc[:2])
    assert speed > 0.2  # it did move
    assert np.linalg.norm(contact_velocity[:2]) < 0.01 * speed


def test_coasting_loses_no_speed_to_the_ball():
    figures = caster_drag.coasting_drag(P)
    # Coasting from 0.5 m/s for 1 s, a drag of DRAG_BOUND on m_eff ≈ 6 kg would
    # decelerate at 1.7e-5 m/s².
    assert abs(figures["caster drag from coasting"]) < DRAG_BOUND


def test_accelerating_ball_carries_its_rolling_inertia_force():
    # Pushed at its centre, a ball rolling without slip needs the floor force
    # f = (I/r²) a = (2/5) m_c a against the motion (I = 2/5 m r²): the sign and size of
    # caster_contact_drag, checked on the speed ramp (a ≈ 1 m/s²). 5 %: the ball's
    # acceleration is taken as the chassis', which differs while the chassis pitches.
    model = caster_drag._model(P)
    data = caster_drag._run(model, P, 0.0, 0.0, caster_drag.SETTLE)
    rows = []
    caster_drag._run(model, P, 0.5, 0.0, 0.3, data, record=lambda d: rows.append(
        (caster_drag.caster_contact_drag(model, d), d.qacc[0])))
    force, accel = np.asarray(rows[50:]).mean(axis=0)
    assert accel > 0.5
    assert force == pytest.approx(0.4 * P.caster.mass * accel, rel=0.05)
