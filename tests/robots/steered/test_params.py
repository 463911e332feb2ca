"""The steered robots' shared parameter checks (``robots/steered/params.py``)."""

from dataclasses import dataclass

import pytest

from wmr_mujoco.models.params.parts import PAIRS_SET_IMPRATIO, WheelParams
from wmr_mujoco.models.params.wheeled import MAX_CHASSIS_EDGE, BallCasterParams
from wmr_mujoco.robots.double_steer.params import DoubleSteerParams
from wmr_mujoco.robots.single_steer.params import SingleSteerParams
from wmr_mujoco.robots.steered import params as steered

WHEEL = WheelParams(radius=0.08, width=0.03, mass=0.4)
CASTER = BallCasterParams(radius=0.02, mass=0.05)


@dataclass(frozen=True)
class Layout:
    """A stand-in steered robot: one layout field ``reach`` in (wheel radius, 1]."""

    wheel: WheelParams = WHEEL
    caster: BallCasterParams = CASTER
    reach: float = 0.5
    chassis_mass: float = 5.0
    chassis_size: tuple[float, float, float] = (0.4, 0.3, 0.05)

    def __post_init__(self) -> None:
        steered.check(self, lambda p: (("reach", p.wheel.radius, 1.0),))


def test_valid_parameters_pass():
    Layout()


@pytest.mark.parametrize("kwargs, message", [
    # every number positive, masses without an upper bound
    ({"chassis_mass": 0.0}, "Layout.chassis_mass = 0.0 is not physical; valid range is "
                            "(0, inf)"),
    # the layout field's own range (low, high]
    ({"reach": 0.08}, "Layout.reach = 0.08 is not physical; valid range is (0.08, 1]"),
    ({"reach": 1.01}, "Layout.reach = 1.01 is not physical; valid range is (0.08, 1]"),
    # the caster below the wheel
    ({"caster": BallCasterParams(radius=0.08, mass=0.05)}, "caster.radius = 0.08 must be "
                                                           "smaller than the wheel radius"),
    # each plate edge in (0, MAX_CHASSIS_EDGE]
    ({"chassis_size": (0.4, MAX_CHASSIS_EDGE + 1.0, 0.05)}, "chassis_size"),
])
def test_each_check_names_the_bad_value(kwargs, message):
    with pytest.raises(ValueError) as err:
        Layout(**kwargs)
    assert message in str(err.value)


def test_a_wheel_of_the_wrong_type_is_named_before_the_layout_reads_it():
    """The layout's bounds read ``wheel.radius``: a wheel that is not a WheelParams is
    named by the type check, not met as an AttributeError."""
    with pytest.raises(ValueError, match="wheel"):
        Layout(wheel=None)


def test_checks_run_in_order_the_first_bad_value_named():
    """A negative mass and an out-of-range layout field: the positivity check comes
    first, so the mass is named."""
    with pytest.raises(ValueError, match="chassis_mass"):
        Layout(chassis_mass=-1.0, reach=5.0)


@pytest.mark.parametrize("cls", [SingleSteerParams, DoubleSteerParams])
def test_both_robots_use_the_shared_unused_fields(cls):
    """The floor pairs set ``impratio`` for both steered robots."""
    assert cls.UNUSED == steered.UNUSED == PAIRS_SET_IMPRATIO
