"""MecanumParams: derived geometry and named errors for bad values."""

import dataclasses
import math

import pytest

from wmr_mujoco.robots.mecanum4.params import MecanumParams

from conftest import assert_bound_edge, assert_count_edge


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


def test_an_integer_field_refuses_a_fraction():
    with pytest.raises(ValueError, match=r"MecanumParams\.rollers_per_wheel = 16\.5 is not an "
                                         r"integer"):
        MecanumParams(rollers_per_wheel=16.5)


#: Each bound at its edge: (class, other fields, field, a value on the edge or just
#: inside it that is valid, one just outside that is not, the range the message must give).
#: Values from the docstring's stated bounds.
EDGES = [
    (MecanumParams, {"half_length": 3.0, "half_track": 3.0}, "wheel_radius", 2.5, 2.51,
     "(0, 2.5]"),
    (MecanumParams, {}, "hub_mass", 1e4, 1.001e4, "(0, 10000]"),
    (MecanumParams, {}, "roller_mass", 0.15, 0.151, "(0, 0.15]"),  # at most the hub
    (MecanumParams, {}, "roller_angle", math.pi / 12, math.pi / 12 - 1e-3,
     "[0.261799, 1.309]"),
    (MecanumParams, {}, "roller_angle", 5 * math.pi / 12, 5 * math.pi / 12 + 1e-3,
     "[0.261799, 1.309]"),
]


@pytest.mark.parametrize("cls, base, field, ok, bad, valid", EDGES,
                         ids=[f"{e[0].__name__}.{e[2]}={e[4]:g}" for e in EDGES])
def test_each_bound_holds_at_its_edge(cls, base, field, ok, bad, valid):
    assert_bound_edge(cls, base, field, ok, bad, valid)


@pytest.mark.parametrize("cls, field, ok, bad, valid", [
    (MecanumParams, "rollers_per_wheel", 24, 25, "[6, 24]"),
    (MecanumParams, "rollers_per_wheel", 6, 5, "[6, 24]"),
])
def test_each_count_holds_at_its_edge(cls, field, ok, bad, valid):
    assert_count_edge(cls, field, ok, bad, valid)


@pytest.mark.parametrize(("robot", "mesh"), [("mecanum4", "profile"), ("omni3", "barrel")])
def test_mesh_rollers_are_refused_with_the_floor_pairs_remedy(robot, mesh):
    from wmr_mujoco.robots import get_spec

    cls = get_spec(robot).params_type
    cls(roller_shape=mesh, floor_impedance=0.0)  # contact bits: allowed
    with pytest.raises(ValueError, match=rf"roller_shape = '{mesh}' with floor_impedance "
                                         r"= 0\.002.*valid: floor_impedance = 0"):
        cls(roller_shape=mesh, floor_impedance=0.002)


@pytest.mark.parametrize(("shape", "thrown"), [("profile", True), ("ellipsoid", False)])
def test_why_a_mesh_roller_is_refused_with_the_remedy(shape, thrown):
    """The refusal's premise, MuJoCo as the oracle: the mesh model (built with contact
    bits, then given the default pairs' remedy parameters and impratio) leaves the floor
    under a mild drive (3-6 rad/s), its base thrown above 20 wheel radii within 3 s;
    the ellipsoid rollers with the same pairs keep it within a millimetre of its rest
    height. If a MuJoCo release makes the mesh stay down, this test says the refusal
    can go."""
    import mujoco
    import numpy as np

    import wmr_mujoco

    remedy = wmr_mujoco.load("mecanum4")
    params = MecanumParams(roller_shape=shape, floor_impedance=0.0)
    model = wmr_mujoco.load("mecanum4", params)
    for name in ("pair_solref", "pair_solreffriction", "pair_solimp", "pair_friction"):
        getattr(model, name)[:] = getattr(remedy, name)
    model.opt.impratio = remedy.opt.impratio
    data = mujoco.MjData(model)
    data.ctrl[:] = np.linspace(3.0, 6.0, model.nu)
    mujoco.mj_forward(model, data)
    rest = data.qpos[2]
    top = rest
    for _ in range(round(3.0 / model.opt.timestep)):
        mujoco.mj_step(model, data)
        top = max(top, data.qpos[2])
    if thrown:
        assert top > 20 * params.wheel_radius
    else:
        assert top - rest < 1e-3
