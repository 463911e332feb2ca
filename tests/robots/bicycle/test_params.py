"""BicycleParams: bounds and named errors for bad values."""

import pytest

from wmr_mujoco.robots.bicycle.params import BicycleParams


def test_bicycle_wheelbase_must_clear_wheels():
    with pytest.raises(ValueError, match=r"BicycleParams\.wheelbase = 0.5.*\(0.68, inf\)"):
        BicycleParams(wheelbase=0.5)
    with pytest.raises(ValueError, match=r"wheelbase = -1"):
        BicycleParams(wheelbase=-1.0)


@pytest.mark.parametrize("make, match", [
    (lambda: BicycleParams(wheelbase=True), r"wheelbase = True is not a number"),
])
def test_wrong_types_are_value_errors_naming_the_field(make, match):
    with pytest.raises(ValueError, match=match):
        make()
