"""Physical parameters of the robots, as frozen dataclasses with validated ranges.

Every length is in metres, every mass in kilograms, every angle in radians, every
rate in rad/s and every torque in N·m. Wheels are modelled, as in the lecture, as
thin uniform discs of radius ``R``, width ``w`` and mass ``m``:

    I_axial    = m R² / 2
    I_diameter = m R² / 4 + m w² / 12

Each dataclass checks its own fields in ``__post_init__`` and raises ``ValueError``
naming the field, its value and the valid range.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields, is_dataclass
from typing import Any, ClassVar, Protocol, TypeVar


def _is_number(value: object) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _check_range(obj: Any, name: str, low: float, high: float = math.inf,
                 low_inclusive: bool = False, high_inclusive: bool = True) -> None:
    """Raise ``ValueError`` unless ``low < obj.name <= high`` (bounds as the flags say).

    A value that is not a number (a string, None, a bool) is refused the same way.
    """
    value = getattr(obj, name)
    ok = _is_number(value) and math.isfinite(value)
    if ok:
        ok = ((value >= low if low_inclusive else value > low)
              and (value <= high if high_inclusive else value < high))
    if not ok:
        bracket = "[" if low_inclusive else "("
        close = "]" if high_inclusive and not math.isinf(high) else ")"
        high_txt = "inf" if math.isinf(high) else f"{high:g}"
        raise ValueError(
            f"{type(obj).__name__}.{name} = {value!r} is not physical; "
            f"valid range is {bracket}{low:g}, {high_txt}{close}"
        )


def _check_count(obj: Any, name: str, low: int, high: int) -> None:
    """Raise ``ValueError`` unless ``obj.name`` is an integer in ``[low, high]``."""
    value = getattr(obj, name)
    if not (isinstance(value, int) and not isinstance(value, bool) and low <= value <= high):
        raise ValueError(f"{type(obj).__name__}.{name} = {value!r}; valid range is "
                         f"integers [{low}, {high}]")


def _check_choice(obj: Any, name: str, choices: tuple[str, ...]) -> None:
    """Raise ``ValueError`` unless ``obj.name`` is one of ``choices``."""
    value = getattr(obj, name)
    if value not in choices:
        raise ValueError(f"{type(obj).__name__}.{name} = {value!r}; valid values are "
                         f"{', '.join(choices)}")


#: Field annotations (as strings: ``from __future__ import annotations``) of numbers.
_NUMBER_TYPES = ("float", "int")
#: Annotations of tuples of numbers, with their lengths.
_TUPLE_TYPES = {"tuple[float, float]": 2, "tuple[float, float, float]": 3,
                "tuple[float, float, float, float]": 4}


def _type_error(obj: Any, name: str, annotation: str, default: object) -> str | None:
    """Why ``obj.name`` does not fit its annotation, or None if it does."""
    value = getattr(obj, name)
    if annotation == "int" and not (isinstance(value, int) and not isinstance(value, bool)):
        return "is not an integer; give an integer"
    if annotation == "float" and not _is_number(value):
        return "is not a number; give a number (SI units)"
    if annotation in _TUPLE_TYPES:
        n = _TUPLE_TYPES[annotation]
        if not (isinstance(value, tuple) and len(value) == n
                and all(_is_number(v) and math.isfinite(v) for v in value)):
            return f"is not {n} finite numbers; give a tuple of {n} numbers (SI units)"
    if annotation == "str" and not isinstance(value, str):
        return "is not a string; give a string"
    if annotation == "bool" and not isinstance(value, bool):
        return "is not True or False; give a bool"
    if is_dataclass(default) and not isinstance(value, type(default)):
        return f"is not a {type(default).__name__}; give a {type(default).__name__}"
    return None


def _check_types(obj: Any) -> None:
    """Raise ``ValueError`` for a field of the wrong type, before any arithmetic on it.

    Number fields (annotated ``float``/``int``) must hold numbers (``int`` fields
    integers); tuple fields a tuple of that many finite numbers; a field whose default is
    a parameter dataclass an instance of that dataclass; ``str``/``bool`` fields a string
    or a bool. The message names the class, the field and the value.
    """
    for f in fields(obj):
        why = _type_error(obj, f.name, str(f.type), f.default)
        if why is not None:
            raise ValueError(f"{type(obj).__name__}.{f.name} = {getattr(obj, f.name)!r} {why}")


def _check_floor_pair(obj: Any) -> None:
    """``floor_impedance`` 0 or in [1e-4, 0.01]."""
    if obj.floor_impedance != 0.0:
        _check_range(obj, "floor_impedance", 1e-4, 0.01, low_inclusive=True)


def _check_positive_fields(obj: Any, exclude: tuple[str, ...] = ()) -> None:
    """Check every field's type, then that each number field not in ``exclude`` is > 0."""
    _check_types(obj)
    for f in fields(obj):
        if f.name not in exclude and _is_number(getattr(obj, f.name)):
            _check_range(obj, f.name, 0.0)


#: Largest wheel radius, m: the biggest tyres built (haul trucks) are about 4 m across.
MAX_WHEEL_RADIUS = 2.5
#: Largest wheel mass, kg: such a tyre with its rim weighs about 5 t.
MAX_WHEEL_MASS = 1.0e4


@dataclass(frozen=True)
class WheelParams:
    """A thin uniform disc wheel; every field has a default (a 0.1 m castor-size wheel).

    Attributes:
        radius: rolling radius R, in (0, 2.5] m: the largest tyres built (haul trucks,
            about 4 m across) bound it from above (:data:`MAX_WHEEL_RADIUS`).
        width: disc thickness w (collision cylinder length), in (0, 2R] m.
        mass: wheel mass m, in (0, 1e4] kg: such a haul-truck tyre with its rim weighs
            about 5 t (:data:`MAX_WHEEL_MASS`).

    """

    radius: float = 0.1
    width: float = 0.03
    mass: float = 0.4

    def __post_init__(self) -> None:
        _check_positive_fields(self)
        _check_range(self, "radius", 0.0, MAX_WHEEL_RADIUS)
        _check_range(self, "mass", 0.0, MAX_WHEEL_MASS)
        _check_range(self, "width", 0.0, 2.0 * self.radius)

    @property
    def axial_inertia(self) -> float:
        """Moment of inertia about the axle, ``m R² / 2``."""
        return 0.5 * self.mass * self.radius**2

    @property
    def diametral_inertia(self) -> float:
        """Moment of inertia about a diameter, ``m R² / 4 + m w² / 12``."""
        return self.mass * (self.radius**2 / 4.0 + self.width**2 / 12.0)


#: Largest motor torque, N·m (see :class:`DriveParams`).
MAX_TORQUE = 1.0e4
#: Largest commanded rate, rad/s (see :class:`DriveParams`).
MAX_RATE = 1.0e3
#: Largest servo gain, N·m·s/rad or N·m/rad (see :class:`DriveParams`).
MAX_GAIN = 1.0e7


#: The steering fields of :class:`DriveParams`, as ``wmr info`` names them: the ``UNUSED``
#: of every robot without steering.
STEERING_FIELDS: tuple[str, ...] = ("drive.steer_kp", "drive.steer_kv",
                                    "drive.steer_torque_limit", "drive.steer_rate_limit",
                                    "drive.steer_angle_limit")


@dataclass(frozen=True)
class DriveParams:
    """Actuator settings shared by every robot.

    Attributes:
        wheel_kv: velocity-servo gain of the wheel motors, N·m·s/rad.
        wheel_armature: reflected rotor inertia ``J_rotor N²`` of each wheel gear motor,
            added to the driven wheel hinges, kg·m². Keep ``wheel_kv · timestep`` at most
            a few times the driven wheel's total inertia: ``implicitfast`` integrates the
            servo damping implicitly but sizes contact forces explicitly, and a much stiffer
            servo on a light wheel lets the robot run ahead of its wheels while accelerating.
        wheel_torque_limit: wheel motor torque limit, N·m.
        wheel_rate_limit: largest commanded wheel rate, rad/s.
        steer_kp: steering servo stiffness, N·m/rad.
        steer_kv: steering servo damping, N·m·s/rad.
        steer_torque_limit: steering torque limit, N·m.
        steer_rate_limit: largest commanded steering rate, rad/s.
        steer_angle_limit: steering angle limit, rad (ignored by the disc, whose
            mount steers freely through any angle).

    Upper bounds, physical: torques at most :data:`MAX_TORQUE` = 1e4 N·m (a wheel hub
    drive of a 100 t vehicle, 1 m wheels, 1 g of traction, shared by 10 wheels, needs
    about 1e5 N / 10 · 1 m = 1e4 N·m); rates at most :data:`MAX_RATE` = 1000 rad/s
    (about 10,000 rpm at the wheel, a motor's speed with no gear); servo gains at most
    what saturates that torque at an error of 1 mrad or 1 mrad/s: ``kv ≤ 1e4 N·m / 1e-3
    rad/s = 1e7`` N·m·s/rad and ``kp ≤ 1e7`` N·m/rad (:data:`MAX_GAIN`); a stiffer servo is
    a bang-bang switch, and ``kv·Δt`` far above the wheel inertia stalls the robot (see
    ``wheel_armature``); armature at most 10 kg·m².

    """

    wheel_kv: float = 5.0
    wheel_armature: float = 0.0
    wheel_torque_limit: float = 20.0
    wheel_rate_limit: float = 40.0
    steer_kp: float = 200.0
    steer_kv: float = 5.0
    steer_torque_limit: float = 20.0
    steer_rate_limit: float = 3.0
    steer_angle_limit: float = 1.0

    def __post_init__(self) -> None:
        _check_positive_fields(self, exclude=("wheel_armature",))
        _check_range(self, "wheel_armature", 0.0, 10.0, low_inclusive=True)
        for name in ("wheel_torque_limit", "steer_torque_limit"):
            _check_range(self, name, 0.0, MAX_TORQUE)
        for name in ("wheel_rate_limit", "steer_rate_limit"):
            _check_range(self, name, 0.0, MAX_RATE)
        for name in ("wheel_kv", "steer_kp", "steer_kv"):
            _check_range(self, name, 0.0, MAX_GAIN)
        _check_range(self, "steer_angle_limit", 0.0, math.pi / 2.0 - 0.05)


@dataclass(frozen=True)
class SimParams:
    """Simulation settings.

    Attributes:
        timestep: integration step, s.
        contact_timeconst: contact ``solref`` time constant, s (MuJoCo clamps it to
            at least twice the timestep).
        impratio: ratio of frictional to normal constraint impedance (elliptic cones).
        friction: sliding friction coefficient between wheels and floor.

    """

    timestep: float = 0.002
    contact_timeconst: float = 0.004
    impratio: float = 10.0
    friction: float = 1.0

    def __post_init__(self) -> None:
        _check_types(self)
        _check_range(self, "timestep", 0.0, 0.02)
        _check_range(self, "contact_timeconst", 0.0, 0.1)
        _check_range(self, "impratio", 1.0, 1000.0, low_inclusive=True)
        _check_range(self, "friction", 0.0, 10.0)


#: Integrators the free disc may use (MuJoCo names).
FREE_INTEGRATORS = ("RK4", "implicit", "implicitfast", "Euler")


@dataclass(frozen=True)
class DiscParams:
    """Single steerable disc on a vertical mount (lecture section 1).

    The mount is a carriage on frictionless x/y/z slides with a steering hinge about
    the vertical; the wheel spins on a hinge in the carriage.

    Attributes:
        wheel: the disc.
        mount_mass: mass of the steering carriage.
        drive: actuator settings.
        sim: simulation settings.
        free_integrator: integrator of the free disc (``disc_free``): ``"RK4"``,
            ``"implicit"``, ``"implicitfast"`` or ``"Euler"``. ``implicitfast`` (and
            ``implicit``, identical here) miss steady precession by an error proportional to
            the timestep; RK4 does not (study table in ``models/disc/README.md``).
        free_timestep: timestep of the free disc, s, in (0, 0.02] like
            :attr:`SimParams.timestep`.
        free_rim: half-thickness of the free disc's collision ellipsoid ``(R, rim, R)``, m,
            in (0, w/2]: physically bounded by the wheel, whose half-width ``w/2`` is the
            thickest rim it has. A thin rim makes a leaning disc touch where a thin disc
            would; the wheel's full half-width puts a leaning disc's contact off the
            thin-disc point and misses steady precession by more than its target (study
            table).
        floor_impedance: impedance ``d`` (``solimp`` d0 = d_width) of the mounted wheel's
            contact pair with the floor, in [1e-4, 0.01] (MuJoCo's least is 1e-4). A
            sliding contact pushes itself off the floor by ``μ d B_f s`` for slip ``s``
            (friction reference damping ``B_f``) against ``(1 − d) g``; a small ``d``
            with ``B_f = 1/Δt`` keeps the wheel down up to ``s = g Δt / (μ d)`` and
            lets friction grip again within one step (derivation in
            ``docs/rolling-disc.md``).
        floor_impratio: ``impratio`` of the mounted disc (its one contact is the wheel's
            with the floor), in [1, 1e6]: the friction-to-normal impedance ratio that makes
            the gripping friction stiff, ``impratio · d (1 + m R²/J) ≫ 1``.

    The mounted disc (``disc``) ignores the ``free_*`` fields and ``sim.impratio``; the free disc
    (``disc_free``, :class:`FreeDiscParams`) ignores the mount and its actuators.

    """

    wheel: WheelParams = WheelParams(radius=0.15, width=0.02, mass=1.5)
    mount_mass: float = 0.5
    drive: DriveParams = DriveParams(wheel_kv=20.0, wheel_torque_limit=5.0,
                                     steer_kp=500.0, steer_kv=2.0)
    sim: SimParams = SimParams()
    free_integrator: str = "RK4"
    free_timestep: float = 0.004
    free_rim: float = 0.002
    floor_impedance: float = 0.001
    floor_impratio: float = 1e4

    #: Fields the model does not use (the mount steers through any angle; the free disc's
    #: settings belong to ``disc_free``; ``floor_impratio`` replaces ``sim.impratio``):
    #: ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = ("drive.steer_angle_limit", "free_integrator",
                                         "free_timestep", "free_rim", "sim.impratio")

    def __post_init__(self) -> None:
        _check_positive_fields(self)
        _check_range(self, "free_timestep", 0.0, 0.02)
        _check_range(self, "free_rim", 0.0, 0.5 * self.wheel.width)
        _check_choice(self, "free_integrator", FREE_INTEGRATORS)
        _check_range(self, "floor_impedance", 1e-4, 0.01, low_inclusive=True)
        _check_range(self, "floor_impratio", 1.0, 1e6, low_inclusive=True)

    @property
    def total_mass(self) -> float:
        """Mass of everything that moves: mount plus disc."""
        return self.mount_mass + self.wheel.mass


@dataclass(frozen=True)
class FreeDiscParams(DiscParams):
    """The same disc on a free joint (``disc_free``): no mount, no actuators.

    Its fields are :class:`DiscParams`'s (one disc, one set of numbers); the free disc
    uses the wheel, the contact settings of ``sim`` and the ``free_*`` fields, and its
    own timestep ``free_timestep`` in place of ``sim.timestep``.
    """

    #: Fields the free disc's model does not use: ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = (
        "mount_mass", "sim.timestep", "floor_impedance", "floor_impratio",
        *(f"drive.{f.name}" for f in fields(DriveParams)))

    @property
    def total_mass(self) -> float:
        """Mass of everything that moves: the disc alone (no mount)."""
        return self.wheel.mass


@dataclass(frozen=True)
class BicycleParams:
    """Planar bicycle (lecture section 2): rear wheel driven, front fork steered.

    The frame moves on x/y/z slides and a yaw hinge: no roll, no pitch, which is how
    the planar model is kept upright. The steering axis is vertical through the front
    wheel centre (no rake, no trail), as in the kinematic model.

    Attributes:
        rear_wheel: the driven rear wheel.
        front_wheel: the free-spinning front wheel.
        wheelbase: distance ℓ between the two wheel centres (and contacts).
        frame_mass: frame mass (CoM at mid-wheelbase).
        fork_mass: steering fork mass.
        drive: actuator settings.
        sim: simulation settings.

    """

    rear_wheel: WheelParams = WheelParams(radius=0.34, width=0.035, mass=1.8)
    front_wheel: WheelParams = WheelParams(radius=0.34, width=0.035, mass=1.4)
    wheelbase: float = 1.05
    frame_mass: float = 10.0
    fork_mass: float = 1.2
    drive: DriveParams = DriveParams(wheel_kv=200.0, wheel_torque_limit=60.0,
                                     steer_kp=1000.0, steer_kv=8.0)
    sim: SimParams = SimParams()

    def __post_init__(self) -> None:
        _check_positive_fields(self)
        min_wb = self.rear_wheel.radius + self.front_wheel.radius
        if self.wheelbase <= min_wb:
            raise ValueError(
                f"BicycleParams.wheelbase = {self.wheelbase!r} makes the wheels overlap; "
                f"valid range is ({min_wb:g}, inf) (sum of the wheel radii)"
            )

    @property
    def total_mass(self) -> float:
        """Mass of frame, fork and both wheels."""
        return self.frame_mass + self.fork_mass + self.rear_wheel.mass + self.front_wheel.mass


@dataclass(frozen=True)
class TricycleParams:
    """Tricycle (lecture section 3): steered front wheel, two rear wheels on one axle.

    The chassis is on a free joint and rests on its three wheels. With
    ``rear_drive="left"`` the left rear wheel is driven and the right one spins freely;
    with ``rear_drive="differential"`` one motor drives both rear wheels through an
    open differential (a fixed tendon ``(θ_L + θ_R)/2``).

    Attributes:
        rear_wheel: each rear wheel.
        front_wheel: the steered front wheel.
        wheelbase: distance ℓ from the rear-axle midpoint to the front contact.
        track: distance w between the rear wheel centre planes.
        chassis_mass: chassis mass (CoM at ``chassis_com_x`` ahead of the rear axle).
        chassis_com_x: CoM position ahead of the rear axle, as a fraction of ℓ.
        fork_mass: steering fork mass.
        rear_drive: ``"left"`` or ``"differential"``.
        drive: actuator settings.
        sim: simulation settings.

    """

    rear_wheel: WheelParams = WheelParams(radius=0.1, width=0.03, mass=0.4)
    front_wheel: WheelParams = WheelParams(radius=0.1, width=0.03, mass=0.4)
    wheelbase: float = 0.5
    track: float = 0.4
    chassis_mass: float = 6.0
    chassis_com_x: float = 0.4
    fork_mass: float = 0.3
    rear_drive: str = "left"
    drive: DriveParams = DriveParams(wheel_kv=10.0, wheel_armature=0.01,
                                     wheel_torque_limit=10.0,
                                     steer_kp=100.0, steer_kv=0.5)
    sim: SimParams = SimParams()

    REAR_DRIVES = ("left", "differential")

    def __post_init__(self) -> None:
        _check_positive_fields(self, exclude=("chassis_com_x",))
        _check_range(self, "chassis_com_x", 0.05, 0.95, low_inclusive=True)
        min_wb = self.rear_wheel.radius + self.front_wheel.radius
        if self.wheelbase <= min_wb:
            raise ValueError(
                f"TricycleParams.wheelbase = {self.wheelbase!r} makes the front wheel "
                f"overlap the rear ones; valid range is ({min_wb:g}, inf) (sum of the "
                "wheel radii)"
            )
        min_track = self.rear_wheel.width + 0.01
        max_track = 2.0 * self.wheelbase
        if not min_track < self.track <= max_track:
            raise ValueError(
                f"TricycleParams.track = {self.track!r} is not physical; valid range is "
                f"({min_track:g}, {max_track:g}] (wider than a rear wheel, at most twice "
                f"the wheelbase)"
            )
        _check_choice(self, "rear_drive", self.REAR_DRIVES)

    @property
    def total_mass(self) -> float:
        """Mass of chassis, fork and the three wheels."""
        return (self.chassis_mass + self.fork_mass + 2.0 * self.rear_wheel.mass
                + self.front_wheel.mass)


@dataclass(frozen=True)
class OmniParams:
    """Three omni wheels at 120° with two staggered rows of passive barrel rollers (§4).

    Wheel i sits at angle ``α_i = 2πi/3`` on a circle of radius ``wheel_distance`` and
    rolls tangentially; each wheel carries ``2 × rollers_per_row`` rollers whose axes are
    tangent to the rim. The rollers' outer surface follows the sphere of radius
    ``wheel_radius`` about the wheel centre (row centre), so the rolling radius is
    ``wheel_radius`` wherever a roller touches.

    Attributes:
        wheel_radius: r, outer radius of the wheel (over the rollers).
        wheel_distance: L, platform centre to wheel contact plane.
        platform_mass: platform mass (a uniform disc for its inertia).
        platform_radius: radius of the platform disc.
        hub_mass: mass of each wheel hub without rollers.
        roller_mass: mass of each roller.
        rollers_per_row: rollers in each of the two rows.
        roller_shape: collision primitive of a roller: ``"barrel"`` (convex mesh of the
            exact profile), ``"ellipsoid"``, ``"capsule"`` or ``"sphere"``.
        roller_thickness: radial thickness of a roller at its middle, as a fraction of r.
        roller_overlap: extra angular span of each roller beyond the ``90°/n`` half-span
            needed for one roller to always touch, as a fraction (the rows overlap).
        row_offset_ratio: axial offset of each row from the wheel mid-plane, as a fraction
            of the roller half-thickness b.
        roller_armature: rotor inertia added to each roller joint, kg·m².
        roller_damping: viscous damping of each roller joint, N·m·s/rad.
        drive: actuator settings (no steering).
        sim: simulation settings.
        floor_impedance: 0 (contact bits, the collision class's contact) or, in
            [1e-4, 0.01], the impedance ``d`` of explicit roller-floor pairs with the
            disc's remedy for a sliding contact that lifts its wheel
            (``docs/floor-contact.md``; an option, not the default: the hybrid model's
            hand-over terms are derived for the collision class's impedance).
    """

    wheel_radius: float = 0.05
    wheel_distance: float = 0.15
    platform_mass: float = 2.0
    platform_radius: float = 0.11
    hub_mass: float = 0.12
    roller_mass: float = 0.005
    rollers_per_row: int = 6
    roller_shape: str = "ellipsoid"
    roller_thickness: float = 0.15
    roller_overlap: float = 0.15
    row_offset_ratio: float = 0.8
    roller_armature: float = 0.0
    roller_damping: float = 0.0
    drive: DriveParams = DriveParams(wheel_kv=2.0, wheel_armature=0.004,
                                     wheel_torque_limit=1.0, wheel_rate_limit=60.0)
    sim: SimParams = SimParams(timestep=0.001, contact_timeconst=0.002)
    floor_impedance: float = 0.0

    ROLLER_SHAPES = ("barrel", "ellipsoid", "capsule", "sphere")
    #: Fields the model does not use (no steering): ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = STEERING_FIELDS

    def __post_init__(self) -> None:
        _check_positive_fields(self, exclude=("roller_armature", "roller_damping",
                                              "row_offset_ratio",
                                              "rollers_per_row", "floor_impedance"))
        _check_floor_pair(self)
        _check_range(self, "roller_armature", 0.0, 1e-3, low_inclusive=True)
        _check_range(self, "roller_damping", 0.0, 1e-2, low_inclusive=True)
        _check_range(self, "roller_thickness", 0.05, 0.8)
        _check_range(self, "roller_overlap", 0.0, 1.0, low_inclusive=True)
        _check_range(self, "row_offset_ratio", 0.0, 3.0, low_inclusive=True)
        _check_count(self, "rollers_per_row", 2, 20)
        _check_choice(self, "roller_shape", self.ROLLER_SHAPES)
        max_r = self.wheel_distance * 0.9
        if self.wheel_radius >= max_r:
            raise ValueError(f"OmniParams.wheel_radius = {self.wheel_radius!r} is too large for "
                             f"wheel_distance {self.wheel_distance:g}; valid range is "
                             f"(0, {max_r:g})")
        _check_range(self, "platform_radius", 0.0, self.wheel_distance)

    @property
    def roller_half_span(self) -> float:
        """Half of the wheel-rotation angle one roller covers: (π/2n)(1 + overlap)."""
        return math.pi / (2 * self.rollers_per_row) * (1.0 + self.roller_overlap)

    @property
    def roller_half_width(self) -> float:
        """Radial half-thickness b of a roller at its middle, ``roller_thickness · r``."""
        return self.roller_thickness * self.wheel_radius

    @property
    def row_offset(self) -> float:
        """Axial offset ±e of the two roller rows from the wheel mid-plane."""
        return self.row_offset_ratio * self.roller_half_width

    @property
    def total_mass(self) -> float:
        """Platform, hubs and rollers."""
        return self.platform_mass + 3 * (self.hub_mass
                                         + 2 * self.rollers_per_row * self.roller_mass)


class RobotParams(Protocol):
    """What generic code uses of a robot's parameter dataclass.

    Every robot's parameters are a frozen dataclass (so ``dataclasses.fields`` and
    ``dataclasses.replace`` work on them) with simulation settings and a total mass.
    """

    __dataclass_fields__: ClassVar[dict[str, Any]]

    @property
    def sim(self) -> SimParams:
        """Simulation settings."""
        ...

    @property
    def total_mass(self) -> float:
        """Mass of everything that moves, kg."""
        ...


ParamsT = TypeVar("ParamsT")


def params_or_default(params: object, params_type: type[ParamsT]) -> ParamsT:
    """``params`` checked against ``params_type``, or its defaults if None.

    Raises:
        ValueError: ``params`` is of another type; the message names both.
    """
    if params is None:
        return params_type()
    if not isinstance(params, params_type):
        raise ValueError(f"params must be a {params_type.__name__}, got "
                         f"{type(params).__name__}")
    return params
