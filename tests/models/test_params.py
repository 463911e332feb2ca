import math
from dataclasses import MISSING, fields, is_dataclass

import pytest

from wmr_mujoco.models.params import DriveParams, SimParams, WheelParams
from wmr_mujoco.models.params.wheeled import BallCasterParams
from wmr_mujoco.robots import ROBOTS

from conftest import assert_bound_edge


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











@pytest.mark.parametrize("cls, field, value", [
    (SimParams, "timestep", 0.0), (SimParams, "timestep", 0.5), (SimParams, "impratio", 0.5),
    (DriveParams, "wheel_kv", 0.0), (DriveParams, "steer_angle_limit", 2.0),
])
def test_other_fields_validated(cls, field, value):
    with pytest.raises(ValueError, match=rf"{cls.__name__}\.{field} = "):
        cls(**{field: value})





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
])
def test_wrong_types_are_value_errors_naming_the_field(make, match):
    with pytest.raises(ValueError, match=match):
        make()





def test_wheel_params_take_only_the_field_to_change():
    default = WheelParams()
    wider = WheelParams(width=0.05)
    assert (wider.radius, wider.mass, wider.width) == (default.radius, default.mass, 0.05)


# --- Every parameter dataclass: the shared parts and every registered robot's --------

def _dataclasses() -> list[type]:
    """The shared parts and every registered robot's parameter dataclasses, nested parts too.

    Read from the registry: a robot added to :data:`wmr_mujoco.robots.ROBOTS` is checked
    here with no edit to this file.
    """
    found: dict[str, type] = {}
    todo = [WheelParams, DriveParams, SimParams, BallCasterParams]
    todo += [s.params_type for s in ROBOTS.values() if s.params_type is not None]
    while todo:
        cls = todo.pop()
        if cls.__qualname__ in found:
            continue
        found[cls.__qualname__] = cls
        todo += [type(f.default) for f in fields(cls) if is_dataclass(f.default)]
    return [found[k] for k in sorted(found)]


ALL_PARAMS = _dataclasses()
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








#: Each bound of the shared parts at its edge (each robot's are in
#: ``tests/robots/<robot>/test_params.py``, through :func:`conftest.assert_bound_edge`):
#: (class, other fields, field, a value on the edge or just inside it that is valid, one
#: just outside that is not, the range the message must give). Values from the docstrings'
#: stated bounds.
EDGES = [
    (BallCasterParams, {"mass": 1e-4}, "radius", 0.002, 0.0019, "[0.002, 0.2]"),
    (BallCasterParams, {}, "radius", 0.2, 0.2001, "[0.002, 0.2]"),
    # a tungsten ball of 0.02 m: 2e4 kg/m³ · 4/3 π 0.02³ m³ = 0.670206 kg
    (BallCasterParams, {}, "mass", 0.67, 0.671, "(0, 0.670206]"),
]


@pytest.mark.parametrize("cls, base, field, ok, bad, valid", EDGES,
                         ids=[f"{e[0].__name__}.{e[2]}={e[4]:g}" for e in EDGES])
def test_each_bound_holds_at_its_edge(cls, base, field, ok, bad, valid):
    assert_bound_edge(cls, base, field, ok, bad, valid)





