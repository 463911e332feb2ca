"""DiffDriveParams: bounds and named errors for bad values."""

import pytest

from wmr_mujoco.robots.diffdrive.params import DiffDriveParams

from conftest import assert_bound_edge


def test_a_chassis_edge_holds_at_5_m():
    DiffDriveParams(chassis_size=(5.0, 0.28, 0.05))
    with pytest.raises(ValueError, match=r"DiffDriveParams\.chassis_size = \(5\.01, 0\.28, "
                                         r"0\.05\) is not physical; valid range of each edge "
                                         r"is \(0, 5\] m"):
        DiffDriveParams(chassis_size=(5.01, 0.28, 0.05))


#: Each bound at its edge: (class, other fields, field, a value on the edge or just
#: inside it that is valid, one just outside that is not, the range the message must give).
#: Values from the docstring's stated bounds.
EDGES = [
    (DiffDriveParams, {}, "track", 2.0, 2.001, "(0.04, 2]"),  # wheel 0.03 m + 0.01 m
    (DiffDriveParams, {}, "track", 0.0401, 0.04, "(0.04, 2]"),
    (DiffDriveParams, {}, "caster_x", -0.1, -0.0999, "(-2, -0.1]"),  # -(R + r_c)
    (DiffDriveParams, {}, "chassis_com_x", 0.0, 0.001, "(-0.25, 0]"),  # caster .. axle
    (DiffDriveParams, {}, "chassis_com_x", -0.2499, -0.25, "(-0.25, 0]"),
]


@pytest.mark.parametrize("cls, base, field, ok, bad, valid", EDGES,
                         ids=[f"{e[0].__name__}.{e[2]}={e[4]:g}" for e in EDGES])
def test_each_bound_holds_at_its_edge(cls, base, field, ok, bad, valid):
    assert_bound_edge(cls, base, field, ok, bad, valid)
