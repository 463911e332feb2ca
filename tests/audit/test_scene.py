"""Bad input fails at once with the file named; a robot file gets a floor."""

from __future__ import annotations

import pytest

from wmr_mujoco.audit.errors import AuditInputError
from wmr_mujoco.audit.scene import ADDED_FLOOR, read_scene

from .conftest import DIFF


def test_missing_file_is_named(tmp_path):
    with pytest.raises(AuditInputError, match="no such file"):
        read_scene(tmp_path / "nope.xml")


def test_not_mjcf_is_named(write):
    path = write("<robot name='urdf'/>", "r.urdf")
    with pytest.raises(AuditInputError, match=r"r\.urdf.*not an MJCF file"):
        read_scene(path)


def test_malformed_xml_names_the_file(write):
    path = write("<mujoco><worldbody><body></worldbody></mujoco>", "broken.xml")
    with pytest.raises(AuditInputError, match=r"broken\.xml"):
        read_scene(path)


def test_robot_file_gets_a_floor_under_its_lowest_collider(write):
    scene = read_scene(write(DIFF))
    assert scene.floor_added
    floor = scene.model.geom(ADDED_FLOOR)
    # Lowest collider: the wheels' spheres, centre z 0.05, radius 0.05 -> 0 (and the skid
    # at 0.05 - 0.03 - 0.02 = 0): the floor sits at z = 0 to rounding.
    assert floor.pos[2] == pytest.approx(0.0, abs=1e-12)
