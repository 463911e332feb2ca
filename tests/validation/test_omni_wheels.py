"""Omni-wheel measurements on omni3's compiled model (issue 3's geometry targets)."""

import numpy as np
import pytest

from wmr_mujoco import load
from wmr_mujoco.analytic import omni_kinematics as ok
from wmr_mujoco.models.params import OmniParams
from wmr_mujoco.validation.omni_wheels import layout_from_model, rolling_radius_profile

WHEELS = ("wheel1", "wheel2", "wheel3")


@pytest.fixture(scope="module")
def omni():
    model = load("omni3")
    return model, layout_from_model(model, WHEELS)


def test_layout_read_from_model_is_the_lecture_geometry(omni):
    _, info = omni
    p = OmniParams()
    # Rolling radius r less half the contact penetration (tens of µm at rest).
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
