"""Every drivable registry entry carries the random-steps family, once."""

from __future__ import annotations

from wmr_mujoco.robots import ROBOTS, get_spec
from wmr_mujoco.robots.floor_steps import with_floor_family
from wmr_mujoco.validation import floor_family as ff


def test_every_drivable_robot_has_the_family_and_the_others_do_not():
    for spec in ROBOTS.values():
        names = [s.name for s in spec.scenarios]
        assert names.count(ff.NAME) == (1 if ff.applies(spec) else 0), spec.name
    # Robots without a kinematic adapter (the Whipple bicycle, the free disc) have none.
    assert not ff.applies(get_spec("whipple"))


def test_adding_twice_adds_once():
    spec = get_spec("omni3")
    assert with_floor_family(spec) is spec
