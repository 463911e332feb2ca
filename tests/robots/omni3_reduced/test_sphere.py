"""The sphere design alternative: a ball joint driven about the axle through a site pair."""

import dataclasses

import mujoco
import numpy as np
import pytest

from wmr_mujoco.models.loading import load
from wmr_mujoco.robots import get_spec
from wmr_mujoco.robots.omni3_reduced import sphere
from wmr_mujoco.robots.omni3_reduced.params import OmniReducedParams
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.validation.adapters import body_twist


@pytest.fixture(scope="module")
def model():
    spec = dataclasses.replace(get_spec("omni3_reduced"), build=sphere.build,
                               scene_extras=sphere.no_pairs)
    return load(spec, OmniReducedParams())


def _angular(model, data, body):
    vel = np.zeros(6)
    mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_BODY, body, vel, 0)
    return vel[:3]


def test_the_site_actuator_drives_the_spin_about_the_chassis_axle(model):
    """The servo's rate is the sphere's angular velocity relative to the platform along
    the axle (the reference site's y axis), at any sphere orientation: after turning and
    rolling sideways, the rate it holds is that, and the platform moves at θ̇ r along the
    wheel's drive direction when only that wheel turns and the others roll."""
    assert model.nv == 6 + 3 * 3 and model.nu == 3
    assert [model.actuator(i).name for i in range(3)] == ["wheel1", "wheel2", "wheel3"]
    data = mujoco.MjData(model)
    # 1 s of one command, then 1 s of another (in seconds: the same motion at any step).
    per_second = round(1.0 / model.opt.timestep)
    for k in range(2 * per_second):
        data.ctrl[:] = (6.0, -2.0, 1.0) if k < per_second else (4.0, 0.0, 0.0)
        mujoco.mj_step(model, data)
    platform = model.body("platform").id
    for i in range(3):
        name = f"wheel{i + 1}"
        axle = data.site_xmat[model.site(f"{name}_axle").id].reshape(3, 3)[:, 1]
        rel = _angular(model, data, model.body(name).id) - _angular(model, data, platform)
        assert data.actuator_velocity[i] == pytest.approx(rel @ axle, abs=1e-9)
    p = OmniReducedParams()
    H = ok.wheel_jacobian(ok.symmetric_layout(p.wheel_radius, p.wheel_distance))
    nu = np.linalg.solve(H, data.actuator_velocity)
    np.testing.assert_allclose(body_twist(model, data), nu, atol=5e-3 * np.abs(nu).max())
    # One contact per wheel, the platform on the floor.
    assert data.ncon == 3
    assert data.qpos[2] == pytest.approx(OmniReducedParams().wheel_radius, abs=1e-3)
