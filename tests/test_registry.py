import pytest

from wmr_mujoco.registry import ROBOTS, get_spec


def test_every_robot_has_files_and_description():
    for spec in ROBOTS.values():
        assert spec.robot_path.is_file(), spec.robot_path
        assert spec.scene_path.is_file(), spec.scene_path
        assert len(spec.description) > 20


def test_unknown_robot_lists_valid_names():
    with pytest.raises(ValueError, match="unknown robot 'unicycle'.*disc, disc_free, bicycle"):
        get_spec("unicycle")
