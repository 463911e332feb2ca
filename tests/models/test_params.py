import math

import pytest

from wmr_mujoco.models.params import (
    BicycleParams,
    DiscParams,
    DriveParams,
    SimParams,
    TricycleParams,
    WheelParams,
)


def test_wheel_inertia_is_thin_disc():
    w = WheelParams(radius=0.2, width=0.02, mass=3.0)
    assert w.axial_inertia == pytest.approx(0.5 * 3.0 * 0.2**2)
    assert w.diametral_inertia == pytest.approx(3.0 * (0.2**2 / 4 + 0.02**2 / 12))


@pytest.mark.parametrize("field, value", [("radius", 0.0), ("radius", -0.1), ("mass", 0.0),
                                          ("width", -1.0), ("radius", math.nan),
                                          ("mass", math.inf)])
def test_wheel_rejects_non_physical(field, value):
    kwargs = {"radius": 0.1, "width": 0.02, "mass": 1.0, field: value}
    with pytest.raises(ValueError, match=rf"WheelParams\.{field} = .*valid range"):
        WheelParams(**kwargs)


def test_wheel_wider_than_diameter_rejected():
    with pytest.raises(ValueError, match=r"width = 0.5.*\(0, 0.2\]"):
        WheelParams(radius=0.1, width=0.5, mass=1.0)


def test_bicycle_wheelbase_must_clear_wheels():
    with pytest.raises(ValueError, match=r"BicycleParams\.wheelbase = 0.5.*\(0.68, inf\)"):
        BicycleParams(wheelbase=0.5)
    with pytest.raises(ValueError, match=r"wheelbase = -1"):
        BicycleParams(wheelbase=-1.0)


@pytest.mark.parametrize("track", [0.01, 1.5, -0.2])
def test_tricycle_track_range(track):
    with pytest.raises(ValueError, match=rf"TricycleParams\.track = {track}.*valid range"):
        TricycleParams(track=track)


def test_tricycle_rear_drive_values():
    with pytest.raises(ValueError, match=r"rear_drive = 'both'.*left, differential"):
        TricycleParams(rear_drive="both")


@pytest.mark.parametrize("cls, field, value", [
    (DiscParams, "mount_mass", 0.0), (TricycleParams, "chassis_mass", -2.0),
    (SimParams, "timestep", 0.0), (SimParams, "timestep", 0.5), (SimParams, "impratio", 0.5),
    (DriveParams, "wheel_kv", 0.0), (DriveParams, "steer_angle_limit", 2.0),
])
def test_other_fields_validated(cls, field, value):
    with pytest.raises(ValueError, match=rf"{cls.__name__}\.{field} = "):
        cls(**{field: value})


def test_total_masses_add_up():
    p = TricycleParams()
    assert p.total_mass == pytest.approx(p.chassis_mass + p.fork_mass + 2 * p.rear_wheel.mass
                                         + p.front_wheel.mass)
