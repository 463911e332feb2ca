"""DoubleSteerParams: bounds and named errors for bad values."""

import pytest

from wmr_mujoco.robots.double_steer.params import DoubleSteerParams

from conftest import assert_bound_edge

#: Each bound at its edge: (class, other fields, field, a value on the edge or just
#: inside it that is valid, one just outside that is not, the range the message must give).
#: Values from the docstring's stated bounds.
EDGES = [
    (DoubleSteerParams, {}, "half_wheelbase", 2.0, 2.01, "(0.09, 2]"),
    (DoubleSteerParams, {}, "half_wheelbase", 0.0901, 0.09, "(0.09, 2]"),
    (DoubleSteerParams, {"chassis_com_y": 0.15}, "caster_y", 2.0, 2.01, "(0.1, 2]"),
    (DoubleSteerParams, {}, "chassis_com_y", 0.18, 0.181, "(0.01, 0.18]"),
]


@pytest.mark.parametrize("cls, base, field, ok, bad, valid", EDGES,
                         ids=[f"{e[0].__name__}.{e[2]}={e[4]:g}" for e in EDGES])
def test_each_bound_holds_at_its_edge(cls, base, field, ok, bad, valid):
    assert_bound_edge(cls, base, field, ok, bad, valid)
