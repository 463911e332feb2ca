"""Inertia about a hinge against MuJoCo's own joint-space mass matrix."""

from dataclasses import replace

import mujoco
import numpy as np
import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.robots.disc.params import DiscParams
from wmr_mujoco.sim.inertia import hinge_inertia


def mass_matrix_diagonal(model, joint):
    """M[i, i] of the joint's dof by the composite rigid body algorithm (independent)."""
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    full = np.zeros((model.nv, model.nv))
    mujoco.mj_fullM(model, data, full)
    dof = model.jnt_dofadr[model.joint(joint).id]
    return full[dof, dof]


@pytest.mark.parametrize("armature", [0.0, 0.01])
def test_wheel_hinge_matches_the_mass_matrix(armature):
    p = DiscParams()
    model = load("disc", replace(p, drive=replace(p.drive, wheel_armature=armature)))
    assert hinge_inertia(model, "wheel") == pytest.approx(
        mass_matrix_diagonal(model, "wheel"), rel=1e-12)
    # And the thin-disc formula plus the armature.
    assert hinge_inertia(model, "wheel") == pytest.approx(
        p.wheel.mass * p.wheel.radius**2 / 2 + armature, rel=1e-12)


def test_steering_hinge_carries_the_subtree_off_axis():
    """The steer hinge moves carriage and wheel: parallel-axis terms included."""
    model = load("disc")
    assert hinge_inertia(model, "steer") == pytest.approx(
        mass_matrix_diagonal(model, "steer"), rel=1e-12)


@pytest.mark.parametrize("joint, match", [("nope", "no such joint"),
                                          ("mount_x", "is not a hinge")])
def test_bad_joint(joint, match):
    with pytest.raises(ValueError, match=match):
        hinge_inertia(load("disc"), joint)
