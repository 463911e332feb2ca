import pytest

from wmr_mujoco.models.export import parameter_table, scene_xml
from wmr_mujoco.robots import ROBOTS


@pytest.mark.parametrize("robot", ["disc", "bicycle", "tricycle", "omni3"])
def test_readme_parameter_tables_are_current(robot):
    spec = ROBOTS[robot]
    readme = (spec.robot_path.parent / "README.md").read_text()
    assert parameter_table(spec) in readme, "run `make models` to refresh the README tables"


@pytest.mark.parametrize("robot", list(ROBOTS))
def test_checked_in_scene_files_are_current(robot):
    spec = ROBOTS[robot]
    assert spec.scene_path.read_text() == scene_xml(spec)
