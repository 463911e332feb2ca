"""The mecanum4 builder: layout, free rollers, envelope, actuation, checked-in files."""

import dataclasses
import math

import mujoco
import numpy as np
import pytest

from wmr_mujoco.models.actuation import set_actuation_mode
from wmr_mujoco.models.builders import mecanum4
from wmr_mujoco.models.loading import load
from wmr_mujoco.models.params_mecanum import MecanumParams
from wmr_mujoco.validation.omni_wheels import rolling_radius_profile


def load_mecanum(params=None):
    return load("mecanum4", params)


@pytest.fixture(scope="module")
def model():
    return load_mecanum(MecanumParams())


def test_contact_roller_axes_make_the_o_layout(model):
    # At rest roller 00 of each wheel is the bottom one; its axis, seen from above, must
    # make γ_i = (−45°, +45°, +45°, −45°) with +x (FL, FR, RL, RR), up to a half turn.
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    for (name, _, _, sg) in mecanum4.WHEELS:
        j = model.joint(f"{name}_roller00").id
        axis = data.xaxis[j]
        assert abs(axis[2]) < 1e-9
        angle = math.atan2(axis[1], axis[0])
        assert math.tan(angle) == pytest.approx(math.tan(sg * math.pi / 4), abs=1e-9)
        assert data.xanchor[j][2] == pytest.approx(MecanumParams().roller_half_width,
                                                   abs=1e-9)  # R − d above the floor


def test_ellipsoid_reaches_past_the_hand_over():
    # Neighbours hand over at φ = π/n; the ellipsoid must extend beyond the ideal
    # profile's axial position there, else the envelope has a gap.
    from wmr_mujoco.analytic import mecanum_roller as mr

    p = MecanumParams()
    t = mr.axis_parameter(p.wheel_radius, p.roller_half_width, p.roller_angle,
                          math.pi / p.rollers_per_wheel)
    sigma, rho = mr.ideal_profile(p.wheel_radius, p.roller_half_width, p.roller_angle, t)
    size = mecanum4.roller_geom_kwargs(p)["size"]
    assert size[2] > sigma > 0.0
    assert rho > 0.0


def test_roller_joints_are_free(model):
    p = MecanumParams()
    rollers = [j for j in range(model.njnt) if "_roller" in model.joint(j).name]
    assert len(rollers) == 4 * p.rollers_per_wheel
    dofs = [model.jnt_dofadr[j] for j in rollers]
    assert not model.dof_damping[dofs].any()
    assert not model.dof_frictionloss[dofs].any()
    assert not model.dof_armature[dofs].any()


def test_profile_mesh_has_no_ripple():
    # The ideal profile as a convex mesh: ripple only from its facets (17 rings × 40).
    model = load_mecanum(dataclasses.replace(MecanumParams(), roller_shape="profile"))
    prof = rolling_radius_profile(model, "wheel_fl", "wheel_fl_roller", samples=121)
    assert 100 * np.ptp(prof) / prof.mean() <= 0.1


def test_torque_mode_applies_the_control():
    m = load_mecanum(MecanumParams())
    set_actuation_mode(m, "torque")
    data = mujoco.MjData(m)
    data.ctrl[:] = 0.5
    mujoco.mj_step(m, data)
    np.testing.assert_allclose(data.actuator_force, 0.5)
