"""Caster robots: checked-in XML, ball caster contacts, torque mode."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco import set_actuation_mode
from wmr_mujoco import wheeled_scenarios as ws
from wmr_mujoco.builders import common
from wmr_mujoco.wheeled_registry import SPECS


@pytest.mark.parametrize("robot", list(SPECS))
def test_builder_defaults_reproduce_checked_in_xml(robot):
    spec = SPECS[robot]
    assert common.to_xml(spec.build(spec.params_type())) == spec.robot_path.read_text()


@pytest.mark.parametrize("robot", list(SPECS))
def test_balls_touch_only_the_floor(robot):
    model = ws.load(robot)
    data = mujoco.MjData(model)
    for _ in range(200):
        mujoco.mj_step(model, data)
    floor = model.geom("floor").id
    pairs = {tuple(sorted(model.geom(g).name for g in data.contact.geom[i]))
             for i in range(data.ncon)}
    assert all("floor" in p for p in pairs)
    balls = [g for g in range(model.ngeom) if model.geom(g).name.endswith("_collision")
             and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_SPHERE]
    assert balls
    for g in balls:
        assert model.geom_contype[g] == 0 and model.geom_conaffinity[g] == 1
        assert tuple(sorted(("floor", model.geom(g).name))) in pairs
    del floor


def test_torque_mode_accelerates_as_newton_says():
    # Equal torques τ on both wheels from rest: a = (2τ/R) / m_eff with
    # m_eff = M + 2 (J_w + J_a)/R² + (2/5) m_c (rolling wheels, rotors and ball).
    p = ws.DiffDriveParams()
    model = ws.load("diffdrive")
    set_actuation_mode(model, "torque")
    data = mujoco.MjData(model)
    for _ in range(150):
        mujoco.mj_step(model, data)
    tau = 0.2
    data.ctrl[:] = tau
    v = []
    for _ in range(500):
        mujoco.mj_step(model, data)
        v.append(data.qvel[0])
    t = model.opt.timestep * np.arange(500)
    a = np.polyfit(t[100:], np.asarray(v)[100:], 1)[0]
    w = p.wheel
    m_eff = (p.total_mass + 2 * (w.axial_inertia + p.drive.wheel_armature) / w.radius**2
             + 0.4 * p.caster.mass)
    # 1 %: rolling radius R − δ/2 (δ ≈ 9 µm, 6e-5) and pitch transients after the step.
    assert a == pytest.approx(2 * tau / w.radius / m_eff, rel=1e-2)
