"""MecanumParams: derived geometry and named errors for bad values."""

import dataclasses
import math

import pytest

from wmr_mujoco.robots.mecanum4.params import MecanumParams


def test_derived_geometry():
    p = MecanumParams()
    b = p.roller_thickness * p.wheel_radius
    assert p.axis_distance == pytest.approx(p.wheel_radius - b)
    assert p.roller_half_span == pytest.approx(math.pi / 16 * 1.1)
    # The contact walks along the axle by y = d tan φ tan γ (docs/mecanum.md §2).
    assert p.wheel_half_width == pytest.approx(
        p.axis_distance * math.tan(p.roller_half_span) + b)
    assert p.total_mass == pytest.approx(3.0 + 4 * (0.15 + 16 * 0.004))


@pytest.mark.parametrize(("field", "value"), [("rollers_per_wheel", 4),
                                              ("rollers_per_wheel", 12.0),
                                              ("roller_shape", "cylinder"),
                                              ("roller_angle", 1.5),
                                              ("half_track", 0.01),
                                              ("half_length", 0.04),
                                              ("roller_thickness", 0.9),
                                              ("roller_damping", -1.0),
                                              ("wheel_radius", float("nan"))])
def test_bad_parameters_are_named(field, value):
    with pytest.raises(ValueError, match=field):
        dataclasses.replace(MecanumParams(), **{field: value})


def test_too_much_overlap_is_named():
    with pytest.raises(ValueError, match="roller_overlap"):
        MecanumParams(rollers_per_wheel=6, roller_overlap=1.0)
