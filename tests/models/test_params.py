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


@pytest.mark.parametrize("make, match", [
    (lambda: WheelParams(radius=1e6), r"WheelParams\.radius = 1000000.0 is not physical; "
                                      r"valid range is \(0, 2.5\]"),
    (lambda: WheelParams(mass=2e4), r"WheelParams\.mass = 20000.0 .*\(0, 10000\]"),
    (lambda: DriveParams(wheel_kv=1e9), r"DriveParams\.wheel_kv = 1000000000.0 is not "
                                        r"physical; valid range is \(0, 1e\+07\]"),
    (lambda: DriveParams(steer_kp=1e9), r"steer_kp = 1000000000.0 .*\(0, 1e\+07\]"),
    (lambda: DriveParams(wheel_torque_limit=1e5), r"wheel_torque_limit = .*\(0, 10000\]"),
    (lambda: DriveParams(wheel_rate_limit=1e4), r"wheel_rate_limit = .*\(0, 1000\]"),
])
def test_physical_upper_bounds(make, match):
    with pytest.raises(ValueError, match=match):
        make()


@pytest.mark.parametrize("make, match", [
    (lambda: WheelParams(radius="0.1"), r"WheelParams\.radius = '0.1' is not a number"),
    (lambda: DriveParams(steer_kp="stiff"), r"DriveParams\.steer_kp = 'stiff' is not a number"),
    (lambda: TricycleParams(track=None), r"TricycleParams\.track = None is not a number"),
    (lambda: BicycleParams(wheelbase=True), r"wheelbase = True is not a number"),
    (lambda: DiscParams(wheel=0.15), r"DiscParams\.wheel = 0.15; give a WheelParams"),
    (lambda: TricycleParams(rear_drive=1), r"rear_drive = 1; give a string"),
])
def test_wrong_types_are_value_errors_naming_the_field(make, match):
    with pytest.raises(ValueError, match=match):
        make()


def test_a_short_tricycle_wheelbase_is_a_wheelbase_error():
    with pytest.raises(ValueError, match=r"TricycleParams\.wheelbase = 0.15 makes the front "
                                         r"wheel overlap the rear ones; valid range is "
                                         r"\(0.2, inf\)"):
        TricycleParams(wheelbase=0.15)


def test_wheel_params_take_only_the_field_to_change():
    default = WheelParams()
    wider = WheelParams(width=0.05)
    assert (wider.radius, wider.mass, wider.width) == (default.radius, default.mass, 0.05)
