import mujoco
import pytest

import wmr_mujoco.validation.spec
from wmr_mujoco import ROBOTS, load
from wmr_mujoco.models.params import WheelParams
from wmr_mujoco.robots.tricycle.params import TricycleParams

from conftest import model_differences


@pytest.mark.parametrize("robot", list(ROBOTS))
def test_builder_defaults_reproduce_checked_in_xml(robot):
    from_file = load(robot)
    from_builder = load(robot, ROBOTS[robot].params_type())
    assert model_differences(from_file, from_builder) == []


def test_model_differences_detects_a_change():
    a = load("disc")
    b = load("disc", ROBOTS["disc"].params_type(
        wheel=WheelParams(radius=0.15, width=0.02, mass=1.6)))
    assert "body_mass" in model_differences(a, b)


def test_parameters_change_the_model():
    model = load("tricycle", TricycleParams(track=0.6))
    left = model.body("rear_left_wheel").pos
    right = model.body("rear_right_wheel").pos
    assert left[1] - right[1] == pytest.approx(0.6)


def test_differential_variant_compiles():
    model = load("tricycle", TricycleParams(rear_drive="differential"))
    assert model.nu == 2 and model.ntendon == 1
    assert model.actuator(0).name == "rear_drive"


def test_wrong_params_type_is_clear():
    with pytest.raises(ValueError, match="must be a DiscParams, got TricycleParams"):
        load("disc", TricycleParams())


def test_missing_model_file_names_path(tmp_path, monkeypatch):
    monkeypatch.setattr(wmr_mujoco.validation.spec, "MODELS_DIR", tmp_path)
    with pytest.raises(FileNotFoundError, match=str(tmp_path / "bicycle" / "scene.xml")):
        load("bicycle")


def test_scene_has_floor_and_light():
    for robot in ROBOTS:
        model = load(robot)
        assert model.geom("floor").type == mujoco.mjtGeom.mjGEOM_PLANE
        assert model.nlight >= 1


def test_a_kept_scene_is_handed_out_as_a_fresh_copy():
    """The cache gives the model a compile gives, and no caller sees another's changes."""
    import copy

    from wmr_mujoco.models import loading

    loading.clear_cache()
    first = load("disc")  # compiled now
    pristine = copy.copy(first)
    first.body_mass[:] = 99.0  # a caller modifying its model
    first.opt.timestep = 0.5
    again = load("disc")  # from the cache
    assert again is not first
    assert model_differences(again, pristine) == []
    built = load("disc", ROBOTS["disc"].params_type())
    built.geom_friction[:] = 0.0
    assert model_differences(load("disc", ROBOTS["disc"].params_type()), pristine) == []
    loading.clear_cache()
    assert model_differences(load("disc"), pristine) == []


def test_a_changed_scene_file_is_compiled_again(tmp_path, monkeypatch):
    import os
    import shutil

    from wmr_mujoco.models import loading

    folder = tmp_path / "disc"
    shutil.copytree(ROBOTS["disc"].scene_path.parent, folder)
    monkeypatch.setattr(wmr_mujoco.validation.spec, "MODELS_DIR", tmp_path)
    before = load("disc").opt.timestep
    scene = folder / ROBOTS["disc"].robot_file
    text = scene.read_text()
    assert f'timestep="{before:g}"' in text
    scene.write_text(text.replace(f'timestep="{before:g}"', 'timestep="0.0005"'))
    stat = scene.stat()
    os.utime(scene, ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**9))  # a later edit
    assert load("disc").opt.timestep == 0.0005
    loading.clear_cache()
