"""DiscParams and FreeDiscParams: bounds and named errors for bad values."""

import pytest

from wmr_mujoco.robots.disc.params import DiscParams

from conftest import assert_bound_edge


def test_free_disc_integrator_is_one_of_mujocos():
    with pytest.raises(ValueError, match=r"DiscParams\.free_integrator = 'rk4'; valid values "
                                         r"are RK4, implicit, implicitfast, Euler"):
        DiscParams(free_integrator="rk4")


def test_mount_mass_is_validated():
    with pytest.raises(ValueError, match=r"DiscParams\.mount_mass = "):
        DiscParams(mount_mass=0.0)


@pytest.mark.parametrize("make, match", [
    (lambda: DiscParams(wheel=0.15), r"DiscParams\.wheel = 0.15 is not a WheelParams; "
                                       r"give a WheelParams"),
])
def test_wrong_types_are_value_errors_naming_the_field(make, match):
    with pytest.raises(ValueError, match=match):
        make()


#: Each bound at its edge: (class, other fields, field, a value on the edge or just
#: inside it that is valid, one just outside that is not, the range the message must give).
#: Values from the docstring's stated bounds.
EDGES = [
    (DiscParams, {}, "free_timestep", 0.02, 0.0201, "(0, 0.02]"),
    (DiscParams, {}, "free_rim", 0.01, 0.0101, "(0, 0.01]"),  # half the 0.02 m width
    (DiscParams, {}, "floor_impedance", 1e-4, 9e-5, "[0.0001, 0.01]"),  # MuJoCo's least d
    (DiscParams, {}, "floor_impedance", 0.01, 0.011, "[0.0001, 0.01]"),
    (DiscParams, {}, "floor_impratio", 1.0, 0.5, "[1, 1e+06]"),
    (DiscParams, {}, "floor_impratio", 1e6, 1.1e6, "[1, 1e+06]"),
]


@pytest.mark.parametrize("cls, base, field, ok, bad, valid", EDGES,
                         ids=[f"{e[0].__name__}.{e[2]}={e[4]:g}" for e in EDGES])
def test_each_bound_holds_at_its_edge(cls, base, field, ok, bad, valid):
    assert_bound_edge(cls, base, field, ok, bad, valid)
