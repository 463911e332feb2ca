import math
from dataclasses import MISSING, fields

import pytest

from wmr_mujoco.models.params import DriveParams, SimParams, WheelParams
from wmr_mujoco.models.params.wheeled import BallCasterParams
from wmr_mujoco.robots.bicycle.params import BicycleParams
from wmr_mujoco.robots.diffdrive.params import DiffDriveParams
from wmr_mujoco.robots.disc.params import DiscParams, FreeDiscParams
from wmr_mujoco.robots.double_steer.params import DoubleSteerParams
from wmr_mujoco.robots.mecanum4.params import MecanumParams
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.single_steer.params import SingleSteerParams
from wmr_mujoco.robots.tricycle.params import TricycleParams
from wmr_mujoco.robots.whipple.params import WhippleParams, WhippleSimParams


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
    (lambda: DiscParams(wheel=0.15), r"DiscParams\.wheel = 0.15 is not a WheelParams; "
                                       r"give a WheelParams"),
    (lambda: TricycleParams(rear_drive=1), r"rear_drive = 1 is not a string; give a string"),
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


# --- Every parameter dataclass, the original robots' and the added ones alike ----------

ALL_PARAMS = [WheelParams, DriveParams, SimParams, DiscParams, FreeDiscParams, BicycleParams,
              TricycleParams, OmniParams, MecanumParams, BallCasterParams, DiffDriveParams,
              SingleSteerParams, DoubleSteerParams, WhippleParams, WhippleSimParams]
ALL_FIELDS = [(cls, f.name) for cls in ALL_PARAMS for f in fields(cls)]

#: What the message says after ``Class.field = value`` for a value of the wrong type,
#: by the field's declared type (independent of the code: the wording users are promised).
_WRONG_TYPE = {
    "float": "is not a number; give a number (SI units)",
    "int": "is not an integer; give an integer",
    "bool": "is not True or False; give a bool",
    "tuple[float, float]": "is not 2 finite numbers; give a tuple of 2 numbers (SI units)",
    "tuple[float, float, float]": "is not 3 finite numbers; give a tuple of 3 numbers "
                                  "(SI units)",
    "tuple[float, float, float, float]": "is not 4 finite numbers; give a tuple of 4 "
                                         "numbers (SI units)",
}


@pytest.mark.parametrize("cls", ALL_PARAMS, ids=lambda c: c.__name__)
def test_every_field_has_a_default(cls):
    assert all(f.default is not MISSING for f in fields(cls))
    cls()


@pytest.mark.parametrize("bad", ["0.1", None], ids=["string", "None"])
@pytest.mark.parametrize("cls, field", ALL_FIELDS,
                         ids=[f"{c.__name__}.{n}" for c, n in ALL_FIELDS])
def test_every_field_refuses_a_string_or_none_naming_field_and_value(cls, field, bad):
    kind = str(next(f.type for f in fields(cls) if f.name == field))
    default = getattr(cls(), field)
    if kind == "str":
        if bad is not None:  # a string of the wrong value: the valid values are listed
            with pytest.raises(ValueError, match=rf"^{cls.__name__}\.{field} = '0\.1'; "
                                                 r"valid values are \w"):
                cls(**{field: bad})
            return
        why = "is not a string; give a string"
    elif kind in _WRONG_TYPE:
        why = _WRONG_TYPE[kind]
    else:  # a nested parameter dataclass
        name = type(default).__name__
        why = f"is not a {name}; give a {name}"
    with pytest.raises(ValueError) as err:
        cls(**{field: bad})
    assert str(err.value) == f"{cls.__name__}.{field} = {bad!r} {why}"


def test_an_integer_field_refuses_a_fraction():
    with pytest.raises(ValueError, match=r"MecanumParams\.rollers_per_wheel = 16\.5 is not an "
                                         r"integer"):
        MecanumParams(rollers_per_wheel=16.5)


def test_free_disc_integrator_is_one_of_mujocos():
    with pytest.raises(ValueError, match=r"DiscParams\.free_integrator = 'rk4'; valid values "
                                         r"are RK4, implicit, implicitfast, Euler"):
        DiscParams(free_integrator="rk4")


#: Each bound of the added robots' parameters at its edge: (class, other fields, field,
#: a value on the edge or just inside it that is valid, one just outside that is not, the
#: range the message must give). Values from the docstrings' stated bounds.
EDGES = [
    (WhippleParams, {}, "gravity", 25.0, 25.01, "(0, 25]"),  # Jupiter
    (WhippleParams, {}, "gravity", 1e-6, 0.0, "(0, 25]"),
    (WhippleParams, {}, "trail", -1.0, -1.001, "[-1, 1]"),
    (WhippleParams, {}, "trail", 1.0, 1.001, "[-1, 1]"),
    (WhippleParams, {}, "head_angle", 1.5707, math.pi / 2, "(-1.5708, 1.5708)"),
    (WhippleParams, {}, "head_angle", -1.5707, -math.pi / 2, "(-1.5708, 1.5708)"),
    (WhippleParams, {"wheelbase": 6.0}, "rear_radius", 2.5, 2.51, "(0, 2.5]"),
    (WhippleParams, {"wheelbase": 6.0}, "front_radius", 2.5, 2.51, "(0, 2.5]"),
    (WhippleParams, {}, "rear_mass", 1e4, 1.001e4, "(0, 10000]"),
    (WhippleParams, {}, "front_mass", 1e4, 1.001e4, "(0, 10000]"),
    (WhippleSimParams, {}, "timestep", 0.01, 0.0101, "(0, 0.01]"),
    (WhippleSimParams, {}, "contact_dampratio", 10.0, 10.01, "(0, 10]"),
    (WhippleSimParams, {}, "solimp_dmax", 0.9999, 1.0, "(0.5, 0.9999]"),
    (WhippleSimParams, {}, "solimp_dmax", 0.5001, 0.5, "(0.5, 0.9999]"),
    (WhippleSimParams, {}, "wheel_half_width", 0.05, 0.0501, "(0, 0.05]"),
    (BallCasterParams, {"mass": 1e-4}, "radius", 0.002, 0.0019, "[0.002, 0.2]"),
    (BallCasterParams, {}, "radius", 0.2, 0.2001, "[0.002, 0.2]"),
    # a tungsten ball of 0.02 m: 2e4 kg/m³ · 4/3 π 0.02³ m³ = 0.670206 kg
    (BallCasterParams, {}, "mass", 0.67, 0.671, "(0, 0.670206]"),
    (DiffDriveParams, {}, "track", 2.0, 2.001, "(0.04, 2]"),  # wheel 0.03 m + 0.01 m
    (DiffDriveParams, {}, "track", 0.0401, 0.04, "(0.04, 2]"),
    (DiffDriveParams, {}, "caster_x", -0.1, -0.0999, "(-2, -0.1]"),  # -(R + r_c)
    (DiffDriveParams, {}, "chassis_com_x", 0.0, 0.001, "(-0.25, 0]"),  # caster .. axle
    (DiffDriveParams, {}, "chassis_com_x", -0.2499, -0.25, "(-0.25, 0]"),
    (SingleSteerParams, {}, "caster_x", 2.0, 2.01, "(0.1, 2]"),
    (SingleSteerParams, {"chassis_com_x": 0.09}, "caster_x", 0.1001, 0.1, "(0.1, 2]"),
    (SingleSteerParams, {}, "caster_y", 1.0, 1.01, "(0.02, 1]"),
    (SingleSteerParams, {}, "chassis_com_x", 0.3039, 0.305, "(0.016, 0.304]"),
    (DoubleSteerParams, {}, "half_wheelbase", 2.0, 2.01, "(0.09, 2]"),
    (DoubleSteerParams, {}, "half_wheelbase", 0.0901, 0.09, "(0.09, 2]"),
    (DoubleSteerParams, {"chassis_com_y": 0.15}, "caster_y", 2.0, 2.01, "(0.1, 2]"),
    (DoubleSteerParams, {}, "chassis_com_y", 0.18, 0.181, "(0.01, 0.18]"),
    (MecanumParams, {"half_length": 3.0, "half_track": 3.0}, "wheel_radius", 2.5, 2.51,
     "(0, 2.5]"),
    (MecanumParams, {}, "hub_mass", 1e4, 1.001e4, "(0, 10000]"),
    (MecanumParams, {}, "roller_mass", 0.15, 0.151, "(0, 0.15]"),  # at most the hub
    (MecanumParams, {}, "roller_angle", math.pi / 12, math.pi / 12 - 1e-3,
     "[0.261799, 1.309]"),
    (MecanumParams, {}, "roller_angle", 5 * math.pi / 12, 5 * math.pi / 12 + 1e-3,
     "[0.261799, 1.309]"),
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
    cls(**base, **{field: ok})
    with pytest.raises(ValueError) as err:
        cls(**base, **{field: bad})
    assert str(err.value) == (f"{cls.__name__}.{field} = {bad!r} is not physical; "
                              f"valid range is {valid}")


@pytest.mark.parametrize("cls, field, ok, bad, valid", [
    (WhippleSimParams, "noslip_iterations", 100, 101, "[0, 100]"),
    (MecanumParams, "rollers_per_wheel", 24, 25, "[6, 24]"),
    (MecanumParams, "rollers_per_wheel", 6, 5, "[6, 24]"),
])
def test_each_count_holds_at_its_edge(cls, field, ok, bad, valid):
    cls(**{field: ok})
    with pytest.raises(ValueError) as err:
        cls(**{field: bad})
    assert str(err.value) == f"{cls.__name__}.{field} = {bad}; valid range is integers {valid}"


def test_a_chassis_edge_holds_at_5_m():
    DiffDriveParams(chassis_size=(5.0, 0.28, 0.05))
    with pytest.raises(ValueError, match=r"DiffDriveParams\.chassis_size = \(5\.01, 0\.28, "
                                         r"0\.05\) is not physical; valid range of each edge "
                                         r"is \(0, 5\] m"):
        DiffDriveParams(chassis_size=(5.01, 0.28, 0.05))
