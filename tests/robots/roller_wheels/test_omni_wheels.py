"""Omni-wheel measurements on omni3's compiled model (issue 3's geometry targets)."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.robots.mecanum4.geometry import layout
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.roller_wheels import (
    drive_from_model,
    dynamics_from_model,
    hybrid_from_model,
    layout_from_model,
    roller_rates,
    rolling_radius_profile,
    static_penetration,
)
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.validation.adapters import body_twist

WHEELS = ("wheel1", "wheel2", "wheel3")


@pytest.fixture(scope="module")
def omni():
    model = load("omni3")
    return model, layout_from_model(model, WHEELS)


def test_layout_read_from_model_is_the_lecture_geometry(omni):
    _, info = omni
    p = OmniParams()
    # Rolling radius r less half the contact penetration (a few µm at rest).
    np.testing.assert_allclose(info.layout.radii, p.wheel_radius, rtol=2e-3)
    H = ok.wheel_jacobian(info.layout) * p.wheel_radius
    np.testing.assert_allclose(H, ok.lecture_matrix(p.wheel_distance), atol=2e-3)
    assert info.angle_servo == (False, False, False)


def test_rolling_radius_ripple(omni):
    model, _ = omni
    profile = rolling_radius_profile(model, "wheel1", "wheel1_roller")
    assert np.ptp(profile) / np.mean(profile) <= 0.005
    assert np.mean(profile) == pytest.approx(OmniParams().wheel_radius, rel=2e-3)


def test_roller_joints_are_free():
    model = load("omni3")
    rollers = [j for j in range(model.njnt) if "roller" in model.joint(j).name]
    assert len(rollers) == 3 * 2 * OmniParams().rollers_per_row
    dofs = [model.jnt_dofadr[j] for j in rollers]
    assert np.all(model.dof_damping[dofs] == 0)
    assert np.all(model.dof_frictionloss[dofs] == 0)
    assert np.all(model.dof_armature[dofs] == 0)


def test_missing_roller_geoms_are_named(omni):
    model, _ = omni
    with pytest.raises(ValueError, match="no collision geoms named 'nothing'"):
        rolling_radius_profile(model, "wheel1", "nothing")


def test_dynamics_from_model_reads_mass_and_wheel_inertia():
    # Independent: the total mass from the parameters; the wheel's inertia at least its
    # armature plus the rollers' masses at the roller-axis distance d.
    p = MecanumParams()
    dyn = dynamics_from_model(load("mecanum4"), layout(p), "chassis", "wheel_fl")
    assert dyn.mass == pytest.approx(p.total_mass, rel=1e-9)
    assert dyn.wheel_inertia > p.drive.wheel_armature + (
        p.rollers_per_wheel * p.roller_mass * p.axis_distance**2)


# --- the hybrid model's parameters read from omni3 (hybrid_from_model) ---------------
HYBRID_WHEELS = ("wheel1", "wheel2", "wheel3")
HYBRID_LAYOUT = ok.symmetric_layout(OmniParams().wheel_radius, OmniParams().wheel_distance)


@pytest.fixture(scope="module")
def omni3_model():
    return load("omni3")


def _hybrid(model):
    return hybrid_from_model(model, HYBRID_LAYOUT, "platform", HYBRID_WHEELS, compliant=False)


def test_parameters_match_the_design(omni3_model):
    """Independent: the OmniParams design values (mass budget, geometry)."""
    p = OmniParams()
    hy = _hybrid(omni3_model)
    # The same reading as the Lagrange model's.
    lag = dynamics_from_model(omni3_model, HYBRID_LAYOUT, "platform", HYBRID_WHEELS[0])
    assert (lag.mass, lag.wheel_inertia) == (hy.mass, hy.wheel_inertia)
    assert lag.yaw_inertia == pytest.approx(hy.inertia[2, 2], rel=1e-12)
    n = 2 * p.rollers_per_row
    assert hy.mass == pytest.approx(p.platform_mass + 3 * (p.hub_mass + n * p.roller_mass))
    assert hy.radius == pytest.approx(p.wheel_radius, rel=1e-9)
    assert hy.distance == pytest.approx(p.wheel_distance, rel=1e-9)
    e = p.row_offset_ratio * p.roller_half_width
    assert sorted(set(np.round(hy.rollers.offsets, 9))) == pytest.approx([-e, e])
    assert hy.wheel_armature == pytest.approx(p.drive.wheel_armature)
    assert hy.penetration == 0.0


def test_lowest_roller_matches_the_collision_geometry(omni3_model):
    """mj_geomDistance to the floor, wheel 1 turned, axle level: the nearest roller geom
    is the one the hybrid model puts in contact (away from the ±0.5° around a hand-over
    where the two are within the geometry's rounding)."""
    hy = _hybrid(omni3_model)
    data = mujoco.MjData(omni3_model)
    floor = omni3_model.geom("floor").id
    wb = omni3_model.joint("wheel1").bodyid[0]
    kids = [b for b in range(omni3_model.nbody) if omni3_model.body_parentid[b] == wb]
    geoms = [next(g for g in range(omni3_model.ngeom) if omni3_model.geom_bodyid[g] == b
                  and omni3_model.geom_conaffinity[g]) for b in kids]
    fromto = np.zeros(6)
    for theta in np.linspace(0, 2 * np.pi, 50):
        phis = np.abs(hy.rollers.phases(theta))
        if abs(np.sort(phis)[1] - np.sort(phis)[0]) < 0.02:
            continue
        data.qpos[:] = omni3_model.qpos0
        data.qpos[2] += 0.5
        data.qpos[omni3_model.joint("wheel1").qposadr[0]] = theta
        mujoco.mj_kinematics(omni3_model, data)
        gaps = [mujoco.mj_geomDistance(omni3_model, data, g, floor, 2.0, fromto) for g in geoms]
        assert int(np.argmin(gaps)) == hy.rollers.lowest(theta)


def test_lift_reproduces_wheel_and_roller_rates(omni3_model):
    """While driving, the constrained wheel and contact-roller rates of the hybrid model
    at the measured twist match the physics within 2 % of the largest (soft contacts
    creep by ~1 %)."""
    hy = _hybrid(omni3_model)
    data = mujoco.MjData(omni3_model)
    H = ok.wheel_jacobian(ok.symmetric_layout(0.05, 0.15))
    acts = [omni3_model.actuator(w).id for w in HYBRID_WHEELS]
    dt = omni3_model.opt.timestep
    for k in range(int(1.2 / dt)):
        data.ctrl[acts] = H @ np.array([0.3, 0.1, 1.0]) * min(1.0, k * dt / 0.5)
        mujoco.mj_step(omni3_model, data)
    mujoco.mj_forward(omni3_model, data)
    th = np.array([data.joint(w).qpos[0] for w in HYBRID_WHEELS])
    modes = hy.modes(th)
    q = hy.lift(body_twist(omni3_model, data), modes, th)
    rates = np.array([data.joint(w).qvel[0] for w in HYBRID_WHEELS])
    spins = roller_rates(omni3_model, data.qvel, HYBRID_WHEELS)[np.arange(3), list(modes)]
    np.testing.assert_allclose(q[6:9], rates, atol=0.02 * np.max(np.abs(rates)))
    np.testing.assert_allclose(q[9:], spins, atol=0.02 * np.max(np.abs(spins)))


def test_drive_and_penetration(omni3_model):
    p = OmniParams()
    servo = drive_from_model(omni3_model, HYBRID_WHEELS[0], "rate")
    assert drive_from_model(omni3_model, HYBRID_WHEELS[0], "torque").mode == "torque"
    assert servo.gain == pytest.approx(p.drive.wheel_kv)
    assert servo.torque_limit == pytest.approx(p.drive.wheel_torque_limit)
    # Soft contact under a third of the weight: µm, far below the roller size.
    assert 1e-6 < static_penetration(omni3_model) < 1e-3


def test_handover_relaxation_reads_the_floor_pair():
    """With floor pairs of small impedance (the sliding remedy) the roller contacts are
    the pairs': ρ is the pair's (its solimp, impratio and direct-form solreffriction),
    1 − d_f at b = 1/Δt, not the geoms' collision-class ρ ≈ 0; the overlap friction's
    time constant is 2 Δt / (1 − ρ), the slip decay rate d_f b it reads as 2/t_c."""
    import dataclasses

    from wmr_mujoco.sim.soft_contact import friction_impedance, impedance, slip_relaxation

    p = dataclasses.replace(OmniParams(), floor_impedance=0.01)
    model = load("omni3", p)
    hy = hybrid_from_model(model, ok.symmetric_layout(p.wheel_radius, p.wheel_distance),
                           "platform", HYBRID_WHEELS)
    k = next(k for k in range(model.npair) if model.pair_solreffriction[k].any())
    solimp = model.pair_solimp[k]
    d_f = friction_impedance(impedance(hy.penetration, solimp), model.opt.impratio)
    assert hy.handover_relaxation == pytest.approx(1.0 - d_f, abs=1e-9)
    assert hy.handover_relaxation == pytest.approx(slip_relaxation(
        model.opt.timestep, model.pair_solref[k, 0], solimp, hy.penetration,
        model.opt.impratio, friction_ref=model.pair_solreffriction[k]), abs=1e-15)
    assert hy.contact_timeconst == pytest.approx(
        2 * model.opt.timestep / (1 - hy.handover_relaxation), rel=1e-12)
    default = hybrid_from_model(load("omni3"), ok.symmetric_layout(p.wheel_radius,
                                                                   p.wheel_distance),
                                "platform", HYBRID_WHEELS)
    assert abs(default.handover_relaxation) < 0.05 < hy.handover_relaxation
