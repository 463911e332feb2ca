"""The scene around a robot: floor, light and sky, and nothing that moves."""

import mujoco
from dm_control import mjcf

from wmr_mujoco.models.builders.scene import add_scene


def test_scene_adds_a_floor_plane_a_light_and_no_degree_of_freedom():
    root = mjcf.RootElement(model="empty")
    add_scene(root)
    physics = mjcf.Physics.from_mjcf_model(root)
    model = physics.model.ptr
    floor = model.geom("floor")
    assert floor.type[0] == mujoco.mjtGeom.mjGEOM_PLANE and floor.bodyid[0] == 0
    assert model.nlight == 1
    assert model.light_type[0] == mujoco.mjtLightType.mjLIGHT_DIRECTIONAL
    assert model.nv == 0 and model.ntex == 2 and model.nmat == 1
