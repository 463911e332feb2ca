"""Ball casters: they touch only the floor, and the rolling-friction switch sets condim."""

import dataclasses

import mujoco
import pytest

from wmr_mujoco.lookup import load
from wmr_mujoco.models.params.wheeled import BallCasterParams
from wmr_mujoco.robots import ROBOTS
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams

#: Every registered robot on ball casters (its parameters have a ``caster`` ball), read
#: from the registry.
CASTER_ROBOTS = [name for name, spec in ROBOTS.items() if spec.params_type is not None
                 and isinstance(getattr(spec.params_type(), "caster", None), BallCasterParams)]


@pytest.mark.parametrize("robot", CASTER_ROBOTS)
def test_balls_touch_only_the_floor(robot):
    model = load(robot)
    data = mujoco.MjData(model)
    for _ in range(200):
        mujoco.mj_step(model, data)
    pairs = {tuple(sorted(model.geom(g).name for g in data.contact.geom[i]))
             for i in range(data.ncon)}
    assert all("floor" in p for p in pairs)
    balls = [g for g in range(model.ngeom) if model.geom(g).name.endswith("_collision")
             and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_SPHERE]
    assert balls
    for g in balls:
        assert model.geom_contype[g] == 0 and model.geom_conaffinity[g] == 1
        assert model.geom_condim[g] == 3  # sliding friction only: rolls and spins freely
        assert tuple(sorted(("floor", model.geom(g).name))) in pairs


def test_rolling_friction_makes_the_ball_contact_condim_6():
    p = DiffDriveParams()
    rolling = dataclasses.replace(p, caster=dataclasses.replace(p.caster,
                                                                rolling_friction=True))
    model = load("diffdrive", rolling)
    assert model.geom_condim[model.geom("caster_collision").id] == 6
