"""WhippleParams: the benchmark's defaults and clear errors for non-physical bicycles."""

from __future__ import annotations

import math

import pytest

from wmr_mujoco.robots.whipple.params import WhippleParams, WhippleSimParams

from conftest import assert_bound_edge, assert_count_edge


def test_defaults_are_table_1():
    p = WhippleParams()
    assert p.total_mass == pytest.approx(94.0, abs=1e-12)  # 2 + 85 + 4 + 3 kg
    assert p.head_angle == pytest.approx(math.pi / 10)
    assert p.tensor("rear_frame_inertia")[0, 2] == 2.4
    assert p.tensor("front_frame_inertia")[2, 0] == -0.00756
    assert p.tensor("front_inertia")[2, 2] == 0.1405  # wheel: I_zz = I_xx


@pytest.mark.parametrize("field, value, words", [
    ("rear_mass", -2.0, "rear_mass"),
    ("front_frame_mass", 0.0, "front_frame_mass"),
    ("rear_frame_inertia", (9.2, 11.0, 2.8, 6.0), "positive definite"),  # xz > sqrt(xx zz)
    ("front_inertia", (0.1405, -0.28), "front_inertia"),
    ("rear_inertia", (0.01, 0.12), "A + B >= C"),  # not a real body: 0.02 < 0.12
    ("head_angle", math.pi / 2, "(-1.5708, 1.5708)"),  # ±π/2, open
    ("head_angle", -2.0, "head_angle"),
    ("rear_radius", 0.7, "overlap"),  # 0.7 + 0.35 > 1.02
    ("rear_frame_com", (0.3, 0.2), "above the floor"),
    ("wheelbase", float("nan"), "wheelbase"),
])
def test_bad_values_raise_naming_field_and_range(field, value, words):
    with pytest.raises(ValueError) as err:
        WhippleParams(**{field: value})
    msg = str(err.value)
    assert words in msg
    assert "valid range" in msg or "must" in msg


@pytest.mark.parametrize("field, value", [("timestep", 0.0), ("integrator", "rk45"),
                                          ("impratio", 0.5), ("solimp_dmax", 1.0),
                                          ("wheel_half_width", -0.001),
                                          ("noslip_iterations", 2.5)])
def test_bad_sim_settings_raise(field, value):
    with pytest.raises(ValueError, match=field):
        WhippleSimParams(**{field: value})


#: Each bound at its edge: (class, other fields, field, a value on the edge or just
#: inside it that is valid, one just outside that is not, the range the message must give).
#: Values from the docstring's stated bounds.
EDGES = [
    (WhippleParams, {}, "gravity", 25.0, 25.01, "(0, 25]"),  # Jupiter
    (WhippleParams, {}, "gravity", 1e-6, 0.0, "(0, 25]"),
    (WhippleParams, {}, "trail", -1.0, -1.001, "[-1, 1]"),
    (WhippleParams, {}, "trail", 1.0, 1.001, "[-1, 1]"),
    (WhippleParams, {}, "head_angle", 1.5707, math.pi / 2, "(-1.5708, 1.5708)"),
    (WhippleParams, {}, "head_angle", -1.5707, -math.pi / 2, "(-1.5708, 1.5708)"),
    (WhippleParams, {"wheelbase": 6.0}, "rear_radius", 2.5, 2.51, "(0, 2.5]"),
    (WhippleParams, {"wheelbase": 6.0}, "front_radius", 2.5, 2.51, "(0, 2.5]"),
    (WhippleParams, {}, "rear_mass", 1e4, 1.001e4, "(0, 10000]"),
    (WhippleParams, {}, "front_mass", 1e4, 1.001e4, "(0, 10000]"),
    (WhippleSimParams, {}, "timestep", 0.01, 0.0101, "(0, 0.01]"),
    (WhippleSimParams, {}, "contact_dampratio", 10.0, 10.01, "(0, 10]"),
    (WhippleSimParams, {}, "solimp_dmax", 0.9999, 1.0, "(0.5, 0.9999]"),
    (WhippleSimParams, {}, "solimp_dmax", 0.5001, 0.5, "(0.5, 0.9999]"),
    (WhippleSimParams, {}, "wheel_half_width", 0.05, 0.0501, "(0, 0.05]"),
]


@pytest.mark.parametrize("cls, base, field, ok, bad, valid", EDGES,
                         ids=[f"{e[0].__name__}.{e[2]}={e[4]:g}" for e in EDGES])
def test_each_bound_holds_at_its_edge(cls, base, field, ok, bad, valid):
    assert_bound_edge(cls, base, field, ok, bad, valid)


@pytest.mark.parametrize("cls, field, ok, bad, valid", [
    (WhippleSimParams, "noslip_iterations", 100, 101, "[0, 100]"),
])
def test_each_count_holds_at_its_edge(cls, field, ok, bad, valid):
    assert_count_edge(cls, field, ok, bad, valid)
