"""Wheels found by the audit: limbs are not wheels; a frictionless skid is a ball caster."""

from __future__ import annotations

import pytest

from wmr_mujoco.audit.errors import NotWheeledError
from wmr_mujoco.audit.scene import read_scene
from wmr_mujoco.audit.wheels import find

from .conftest import DIFF, LEGS, anchor


def test_legs_are_not_wheels(write):
    with pytest.raises(NotWheeledError, match="not a wheeled robot") as err:
        find(read_scene(write(LEGS)).model)
    assert "round about" in str(err.value)


def test_sphere_wheels_and_frictionless_skid(write):
    found = find(read_scene(write(DIFF)).model)
    assert found.classification.robot_class == (2, 0)
    assert [w.kind for w in found.wheels] == ["fixed", "fixed"]
    # Sphere wheels: the envelope is the sphere, radius 0.05 exactly.
    assert [w.radius for w in found.wheels] == pytest.approx([0.05, 0.05], abs=1e-12)
    assert all(w.driven for w in found.wheels)


def test_caster_without_swivel_is_set_aside_as_scrubbing():
    found = find(read_scene(anchor("andino")).model)
    assert found.classification.robot_class == (2, 0)
    assert [w.kind for w in found.scrubbing] == ["fixed"]
    assert not found.scrubbing[0].driven
