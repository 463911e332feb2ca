"""SingleSteerParams: bounds and named errors for bad values."""

import pytest

from wmr_mujoco.robots.single_steer.params import SingleSteerParams

from conftest import assert_bound_edge

#: Each bound at its edge: (class, other fields, field, a value on the edge or just
#: inside it that is valid, one just outside that is not, the range the message must give).
#: Values from the docstring's stated bounds.
EDGES = [
    (SingleSteerParams, {}, "caster_x", 2.0, 2.01, "(0.1, 2]"),
    (SingleSteerParams, {"chassis_com_x": 0.09}, "caster_x", 0.1001, 0.1, "(0.1, 2]"),
    (SingleSteerParams, {}, "caster_y", 1.0, 1.01, "(0.02, 1]"),
    (SingleSteerParams, {}, "chassis_com_x", 0.3039, 0.305, "(0.016, 0.304]"),
]


@pytest.mark.parametrize("cls, base, field, ok, bad, valid", EDGES,
                         ids=[f"{e[0].__name__}.{e[2]}={e[4]:g}" for e in EDGES])
def test_each_bound_holds_at_its_edge(cls, base, field, ok, bad, valid):
    assert_bound_edge(cls, base, field, ok, bad, valid)
