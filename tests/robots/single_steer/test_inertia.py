"""single_steer's sleigh mass data against MuJoCo's compiled model."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.robots.single_steer.inertia import sleigh_inertia
from wmr_mujoco.robots.single_steer.params import SingleSteerParams


def test_sleigh_mass_data_match_the_compiled_model():
    # Independent: sum MuJoCo's own body masses and inertias about the steering axis.
    p = SingleSteerParams()
    model = load("single_steer")
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    pivot = data.site_xpos[model.site("base").id]
    rigid_mass, first, yaw = 0.0, np.zeros(2), 0.0
    fork_yaw = 0.0
    for b in range(1, model.nbody):
        name = model.body(b).name
        m = model.body_mass[b]
        d = data.xipos[b][:2] - pivot[:2]
        izz = (data.ximat[b].reshape(3, 3) @ np.diag(model.body_inertia[b])
               @ data.ximat[b].reshape(3, 3).T)[2, 2]
        if name.startswith("caster"):
            m = 1.4 * m  # a rolling ball: (7/5) m at its centre, no yaw inertia
            izz = 0.0
        if name in ("drive_fork", "drive_wheel"):
            fork_yaw += izz
            izz = 0.0
        rigid_mass += m
        first += m * d
        yaw += izz + m * d @ d
    got = sleigh_inertia(p)
    assert got.mass == pytest.approx(rigid_mass)
    assert got.com == pytest.approx(tuple(first / rigid_mass), abs=1e-12)
    assert got.yaw_inertia == pytest.approx(yaw)
    assert got.fork_inertia == pytest.approx(fork_yaw)
