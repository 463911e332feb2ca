"""The differential drive in torque mode accelerates as Newton's second law says."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.models.actuation import ActuationMode, set_actuation_mode
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams


def test_torque_mode_accelerates_as_newton_says():
    # Equal torques τ on both wheels from rest: a = (2τ/R) / m_eff with
    # m_eff = M + 2 (J_w + J_a)/R² + (2/5) m_c (rolling wheels, rotors and ball).
    p = DiffDriveParams()
    model = load("diffdrive")
    set_actuation_mode(model, ActuationMode.TORQUE)
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
