"""``build_robot``: the stepping API from a registry entry, without the registry."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from wmr_mujoco.loop.build import backends, build_robot
from wmr_mujoco.robots import ROBOTS


def unregistered(name: str):
    """A copy of a robot's entry under a name the registry does not know."""
    return dataclasses.replace(ROBOTS[name], name=f"{name}_copy", scenarios=(), clips=(),
                               demo_scenario=None, bench_scenario=None, render_scenario=None)


def test_a_spec_the_registry_does_not_know_is_driven_like_the_registered_one() -> None:
    # Same model, same command map: the same state after the same commands, bit for bit
    # (nothing is looked up by name).
    runs = []
    for spec in (ROBOTS["diffdrive"], unregistered("diffdrive")):
        robot = build_robot(spec, "mujoco", 0.02)
        robot.reset(pose=(0.1, -0.2, 0.3))
        for _ in range(10):
            state = robot.step((0.3, 0.4))
        runs.append(np.array(state.pose))
    np.testing.assert_array_equal(runs[0], runs[1])


@pytest.mark.parametrize(("name", "expected"), [
    ("diffdrive", ["mujoco", "kinematic"]), ("mecanum4", ["mujoco", "kinematic", "dynamic"]),
    ("omni3", ["mujoco", "kinematic", "dynamic"]),
    ("whipple", ["mujoco"]), ("disc_free", [])])
def test_backends_lists_what_each_robot_has(name: str, expected: list[str]) -> None:
    assert backends(ROBOTS[name]) == expected


def test_a_robot_without_a_command_map_is_refused_by_name() -> None:
    with pytest.raises(ValueError, match="'disc_free' has no actuators"):
        build_robot(ROBOTS["disc_free"])
    with pytest.raises(ValueError, match="no kinematic model; its backends: mujoco"):
        build_robot(ROBOTS["whipple"], "kinematic")
