"""The caster robots' model folders agree with the code that writes them."""

import pytest

from wmr_mujoco import wheeled_export
from wmr_mujoco.export import parameter_table, scene_xml
from wmr_mujoco.markers import markers
from wmr_mujoco.wheeled_registry import SPECS, get_spec


def _between(text: str, key: str) -> str:
    begin, end = markers(key)
    return text.split(begin, 1)[1].split(end, 1)[0].strip()


@pytest.mark.parametrize("robot", list(SPECS))
def test_folder_has_readme_changelog_picture_and_current_tables(robot):
    spec = SPECS[robot]
    folder = spec.robot_path.parent
    for f in ("README.md", "CHANGELOG.md", f"{robot}.png", f"{robot}.xml", "scene.xml"):
        assert (folder / f).is_file(), f
    readme = (folder / "README.md").read_text()
    assert _between(readme, f"{robot} parameters") == parameter_table(spec)
    assert spec.scene_path.read_text() == scene_xml(spec)
    assert f"| {robot} |" in _between(readme, f"{robot} validation")


def test_class_table_lists_every_class():
    table = wheeled_export.class_table()
    for cls in ("(3,0)", "(2,0)", "(2,1)", "(1,1)", "(1,2)"):
        assert f"| {cls} |" in table


def test_unknown_robot_is_a_clear_error():
    with pytest.raises(ValueError, match="valid robots are"):
        get_spec("unicorn")
