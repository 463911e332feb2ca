"""The hybrid model's parameters read from the compiled omni3 model."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco.analytic import omni_kinematics as ok
from wmr_mujoco.models.loading import load
from wmr_mujoco.models.params import OmniParams
from wmr_mujoco.robots.omni3.model import (
    WHEELS,
    drive_from_model,
    dynamics_from_model,
    hybrid_from_model,
    roller_rates,
    static_penetration,
)


@pytest.fixture(scope="module")
def model():
    return load("omni3")


def test_parameters_match_the_design(model):
    """Independent: the OmniParams design values (mass budget, geometry)."""
    p = OmniParams()
    hy = hybrid_from_model(model, compliant=False)
    lag = dynamics_from_model(model)  # the same reading, without rows and rollers
    assert (lag.mass, lag.yaw_inertia, lag.wheel_inertia) == (
        hy.mass, hy.inertia[2, 2], hy.wheel_inertia)
    n = 2 * p.rollers_per_row
    assert hy.mass == pytest.approx(p.platform_mass + 3 * (p.hub_mass + n * p.roller_mass))
    assert hy.radius == pytest.approx(p.wheel_radius, rel=1e-9)
    assert hy.distance == pytest.approx(p.wheel_distance, rel=1e-9)
    e = p.row_offset_ratio * p.roller_half_width
    assert sorted(set(np.round(hy.rollers.offsets, 9))) == pytest.approx([-e, e])
    assert hy.wheel_armature == pytest.approx(p.drive.wheel_armature)
    assert hy.penetration == 0.0


def test_lowest_roller_matches_the_collision_geometry(model):
    """mj_geomDistance to the floor, wheel 1 turned, axle level: the nearest roller geom
    is the one the hybrid model puts in contact (away from the ±0.5° around a hand-over
    where the two are within the geometry's rounding)."""
    hy = hybrid_from_model(model, compliant=False)
    data = mujoco.MjData(model)
    floor = model.geom("floor").id
    wb = model.joint("wheel1").bodyid[0]
    kids = [b for b in range(model.nbody) if model.body_parentid[b] == wb]
    geoms = [next(g for g in range(model.ngeom) if model.geom_bodyid[g] == b
                  and model.geom_conaffinity[g]) for b in kids]
    fromto = np.zeros(6)
    for theta in np.linspace(0, 2 * np.pi, 50):
        phis = np.abs(hy.rollers.phases(theta))
        if abs(np.sort(phis)[1] - np.sort(phis)[0]) < 0.02:
            continue
        data.qpos[:] = model.qpos0
        data.qpos[2] += 0.5
        data.qpos[model.joint("wheel1").qposadr[0]] = theta
        mujoco.mj_kinematics(model, data)
        gaps = [mujoco.mj_geomDistance(model, data, g, floor, 2.0, fromto) for g in geoms]
        assert int(np.argmin(gaps)) == hy.rollers.lowest(theta)


def test_lift_reproduces_wheel_and_roller_rates(model):
    """While driving, the constrained wheel and contact-roller rates of the hybrid model
    at the measured twist match the physics within 2 % of the largest (soft contacts
    creep by ~1 %)."""
    hy = hybrid_from_model(model, compliant=False)
    data = mujoco.MjData(model)
    H = ok.wheel_jacobian(ok.symmetric_layout(0.05, 0.15))
    acts = [model.actuator(w).id for w in WHEELS]
    dt = model.opt.timestep
    for k in range(int(1.2 / dt)):
        data.ctrl[acts] = H @ np.array([0.3, 0.1, 1.0]) * min(1.0, k * dt / 0.5)
        mujoco.mj_step(model, data)
    mujoco.mj_forward(model, data)
    from wmr_mujoco.validation.adapters import body_twist
    th = np.array([data.joint(w).qpos[0] for w in WHEELS])
    modes = hy.modes(th)
    q = hy.lift(body_twist(model, data), modes, th)
    rates = np.array([data.joint(w).qvel[0] for w in WHEELS])
    spins = roller_rates(model, data)[np.arange(3), list(modes)]
    np.testing.assert_allclose(q[6:9], rates, atol=0.02 * np.max(np.abs(rates)))
    np.testing.assert_allclose(q[9:], spins, atol=0.02 * np.max(np.abs(spins)))


def test_drive_and_penetration(model):
    p = OmniParams()
    servo = drive_from_model(model, "rate")
    assert drive_from_model(model, "torque").mode == "torque"
    assert servo.gain == pytest.approx(p.drive.wheel_kv)
    assert servo.torque_limit == pytest.approx(p.drive.wheel_torque_limit)
    # Soft contact under a third of the weight: tens of µm, far below the roller size.
    assert 1e-6 < static_penetration(model) < 1e-3
