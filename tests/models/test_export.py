import pytest

from wmr_mujoco.models.export import parameter_table, scene_xml
from wmr_mujoco.robots import ROBOTS


@pytest.mark.parametrize("robot", ["disc", "bicycle", "tricycle", "omni3", "diffdrive",
                                   "single_steer", "double_steer"])
def test_readme_parameter_tables_are_current(robot):
    spec = ROBOTS[robot]
    readme = (spec.robot_path.parent / "README.md").read_text()
    assert parameter_table(spec) in readme, "run `make models` to refresh the README tables"


@pytest.mark.parametrize("robot", list(ROBOTS))
def test_checked_in_scene_files_are_current(robot):
    spec = ROBOTS[robot]
    assert spec.scene_path.read_text() == scene_xml(spec)


def test_readme_class_table_is_current():
    from wmr_mujoco.docs_sync.markers import markers
    from wmr_mujoco.models.classify import class_table
    from wmr_mujoco.models.export import CLASS_TABLE_KEY
    from wmr_mujoco.models.loading import load
    from wmr_mujoco.models.paths import README_PATH

    begin, end = markers(CLASS_TABLE_KEY)
    section = README_PATH.read_text().split(begin, 1)[1].split(end, 1)[0].strip()
    assert section == class_table({n: load(n) for n in ROBOTS}), "run `make models`"
