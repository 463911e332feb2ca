"""TricycleParams: bounds and named errors for bad values."""

import pytest

from wmr_mujoco.robots.tricycle.params import TricycleParams


@pytest.mark.parametrize("track", [0.01, 1.5, -0.2])
def test_tricycle_track_range(track):
    with pytest.raises(ValueError, match=rf"TricycleParams\.track = {track}.*valid range"):
        TricycleParams(track=track)


def test_tricycle_rear_drive_values():
    with pytest.raises(ValueError, match=r"rear_drive = 'both'.*left, differential"):
        TricycleParams(rear_drive="both")


def test_total_masses_add_up():
    p = TricycleParams()
    assert p.total_mass == pytest.approx(p.chassis_mass + p.fork_mass + 2 * p.rear_wheel.mass
                                         + p.front_wheel.mass)


def test_a_short_tricycle_wheelbase_is_a_wheelbase_error():
    with pytest.raises(ValueError, match=r"TricycleParams\.wheelbase = 0.15 makes the front "
                                         r"wheel overlap the rear ones; valid range is "
                                         r"\(0.2, inf\)"):
        TricycleParams(wheelbase=0.15)


def test_chassis_mass_is_validated():
    with pytest.raises(ValueError, match=r"TricycleParams\.chassis_mass = "):
        TricycleParams(chassis_mass=-2.0)


@pytest.mark.parametrize("make, match", [
    (lambda: TricycleParams(track=None), r"TricycleParams\.track = None is not a number"),
    (lambda: TricycleParams(rear_drive=1), r"rear_drive = 1 is not a string; give a string"),
])
def test_wrong_types_are_value_errors_naming_the_field(make, match):
    with pytest.raises(ValueError, match=match):
        make()
