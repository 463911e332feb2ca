"""Masses and inertias of the compiled models against the documented parameters."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco import ROBOTS, load
from wmr_mujoco.models.builders.common import to_xml
from wmr_mujoco.models.builders.disc import build
from wmr_mujoco.models.params import DiscParams

WHEELS = {
    "disc": {"wheel": lambda p: p.wheel},
    "bicycle": {"rear_wheel": lambda p: p.rear_wheel, "front_wheel": lambda p: p.front_wheel},
    "tricycle": {"rear_left_wheel": lambda p: p.rear_wheel,
                 "rear_right_wheel": lambda p: p.rear_wheel,
                 "front_wheel": lambda p: p.front_wheel},
}


def _inertia_about_joint_axis(model: mujoco.MjModel, joint: str) -> float:
    j = model.joint(joint)
    body = j.bodyid[0]
    rot = np.zeros(9)
    mujoco.mju_quat2Mat(rot, model.body_iquat[body])
    rot = rot.reshape(3, 3)
    inertia = rot @ np.diag(model.body_inertia[body]) @ rot.T
    axis = j.axis if hasattr(j, "axis") else model.jnt_axis[j.id]
    return float(axis @ inertia @ axis)


@pytest.mark.parametrize("robot", list(WHEELS))
def test_total_mass_and_wheel_axial_inertia(robot):
    params = ROBOTS[robot].params_type()
    model = load(robot)
    assert sum(model.body_mass[1:]) == pytest.approx(params.total_mass, rel=1e-12)
    for joint, wheel_of in WHEELS[robot].items():
        w = wheel_of(params)
        assert _inertia_about_joint_axis(model, joint) == pytest.approx(
            0.5 * w.mass * w.radius**2, rel=1e-12)


def test_free_disc_is_one_rigid_disc():
    params = ROBOTS["disc_free"].params_type()
    model = load("disc_free")
    assert model.nbody == 2 and model.nv == 6
    w = params.wheel
    np.testing.assert_allclose(sorted(model.body_inertia[1]), sorted(
        [0.5 * w.mass * w.radius**2] + [w.mass * (w.radius**2 / 4 + w.width**2 / 12)] * 2))


def test_exported_xml_is_clean():
    text = to_xml(build(DiscParams()))
    assert 'class="/"' not in text and "unnamed" not in text
    assert "0.15" in text and "0.1499999" not in text
