"""``wmr info``: the Campion class line, and a foreign scene file described by path."""

import pytest

from wmr_mujoco.info import describe, describe_file
from wmr_mujoco.robots import ROBOTS, get_spec


def test_info_shows_the_computed_class():
    assert ("Campion class: wheels: 2 steerable, 1 ball; δm = 1, δs = 2, δM = 3; class (1,2)"
            in describe("double_steer"))


def test_info_says_why_a_model_has_no_class():
    assert "Campion class: none (no wheels" in describe("disc_free")


def test_info_on_a_scene_file_reads_it_and_leaves_the_registry_alone():
    before = list(ROBOTS)
    text = describe_file(get_spec("diffdrive").scene_path)
    assert "class (2,0)" in text and "parameters: none" in text
    assert list(ROBOTS) == before


def test_info_on_a_missing_file_is_a_clear_error(tmp_path):
    with pytest.raises(ValueError, match="not found"):
        describe_file(tmp_path / "none.xml")
