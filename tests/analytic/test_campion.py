"""The rank theory of Campion classes on wheel sets built by hand (no MuJoCo)."""

import math

import numpy as np
import pytest

from wmr_mujoco.analytic import campion


def _wheel(kind, pos, axle):
    return campion.Wheel(f"{kind}{pos}", kind, pos, axle)


def test_sliding_row_annihilates_rolling_along_the_wheel():
    # A wheel at p with axle a: the contact velocity (u − r p_y, v + r p_x) along a is 0
    # for the pure rotation about the contact point, ν = (r p_y, −r p_x, r).
    p, a = (0.3, -0.2), np.array([0.6, 0.8])
    nu = np.array([p[1], -p[0], 1.0])
    assert campion.sliding_row(p, a) @ nu == pytest.approx(0.0, abs=1e-15)
    # ... and translation along a is forbidden: row · (a, 0) = |a|² = 1.
    assert campion.sliding_row(p, a) @ np.array([0.6, 0.8, 0.0]) == pytest.approx(1.0)


def test_three_steerable_wheels_need_coordinated_steering():
    wheels = tuple(_wheel("steerable", (0.2 * math.cos(a), 0.2 * math.sin(a)), (0.0, 1.0))
                   for a in (0.0, 2.1, 4.2))
    c = campion.classify_wheels(wheels)
    assert c.robot_class == (1, 2)
    assert any("coordinated" in n for n in c.notes)


def test_fixed_wheels_on_two_axles_are_outside_the_theory():
    wheels = (_wheel("fixed", (0.2, 0.0), (0.0, 1.0)), _wheel("fixed", (0.0, 0.2), (1.0, 0.0)))
    c = campion.classify_wheels(wheels)
    assert c.robot_class is None
    assert "more than one axle" in c.reason


#: The five classes from wheel sets laid out by hand (Campion et al. 1996, Table I;
#: Siegwart & Nourbakhsh §3.3): the ranks are those of the sliding rows written out.
HAND_SETS = {
    (3, 0): (("swedish", (0.2, 0.0), (1.0, 0.0)), ("swedish", (-0.1, 0.17), (1.0, 0.0)),
             ("swedish", (-0.1, -0.17), (1.0, 0.0))),
    (2, 0): (("fixed", (0.0, 0.15), (0.0, 1.0)), ("fixed", (0.0, -0.15), (0.0, 1.0)),
             ("ball", (-0.2, 0.0), (0.0, 0.0))),
    (2, 1): (("steerable", (0.2, 0.0), (0.0, 1.0)), ("ball", (-0.1, 0.1), (0.0, 0.0)),
             ("ball", (-0.1, -0.1), (0.0, 0.0))),
    (1, 1): (("fixed", (0.0, 0.0), (0.0, 1.0)), ("steerable", (0.5, 0.0), (0.0, 1.0))),
    (1, 2): (("steerable", (0.2, 0.0), (0.0, 1.0)), ("steerable", (-0.2, 0.0), (0.0, 1.0)),
             ("ball", (0.0, 0.1), (0.0, 0.0))),
}


@pytest.mark.parametrize("cls", list(HAND_SETS))
def test_the_five_classes_from_hand_made_wheel_sets(cls):
    c = campion.classify_wheels(tuple(_wheel(k, p, a) for k, p, a in HAND_SETS[cls]))
    assert c.robot_class == cls
    assert c.manoeuvrability == sum(cls)
