"""The learning settings in the registry entries (robots/learning.py, RobotSpec.learning)."""

import pytest

from wmr_mujoco.robots import ROBOTS
from wmr_mujoco.robots.learning import DEFAULT, PHYSICAL, Bands, Learning
from wmr_mujoco.robots.spec import RobotSpec


def test_every_drivable_robot_declares_its_settings():
    # The environments read them from the entry; a drivable robot without them would get
    # the default scale (1 m), wrong for a small or a large robot.
    missing = [n for n, s in ROBOTS.items() if s.command is not None and s.learning is None]
    assert missing == []


def test_registry_entries_are_the_registry_spec_with_the_field():
    assert all(isinstance(s, RobotSpec) for s in ROBOTS.values())


@pytest.mark.parametrize("field", ["scale", "max_curvature", "control_period"])
@pytest.mark.parametrize("value", [0.0, -1.0, float("nan"), float("inf"), True, "1"])
def test_bad_sizes_are_refused(field, value):
    with pytest.raises(ValueError, match=field):
        Learning(**{field: value})


def test_no_tasks_is_refused():
    with pytest.raises(ValueError, match="tasks"):
        Learning(tasks=())


@pytest.mark.parametrize("name", sorted(PHYSICAL))
def test_bands_outside_the_physical_range_are_refused(name):
    lo, hi = PHYSICAL[name]
    with pytest.raises(ValueError, match=name):
        Bands(**{name: (lo * 0.99, hi)})
    with pytest.raises(ValueError, match=name):
        Bands(**{name: (1.0, hi * 1.01)})
    Bands(**{name: (lo, hi)})  # the edges are physical


def test_default_has_no_radius_band():
    # A robot not described may roll on rollers, whose radius is no single geom's.
    assert DEFAULT.bands.wheel_radius is None


@pytest.mark.parametrize("arm", ["not a name", 1.0, None])
def test_a_steer_arm_must_name_a_parameter(arm):
    with pytest.raises(ValueError, match="steer_arm"):
        Learning(steer_arm=arm)


def test_declared_steer_arms_are_fields_of_the_robots_parameters():
    # The scripted controllers read the arm from the parameters by this name.
    for name, spec in ROBOTS.items():
        arm = spec.learning.steer_arm if spec.learning is not None else ""
        if arm:
            assert hasattr(spec.params_type(), arm), name
