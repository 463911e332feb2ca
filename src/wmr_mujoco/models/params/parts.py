"""The parts every robot shares: wheels, drives and simulation settings.

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
from dataclasses import dataclass

from wmr_mujoco.models.params.fields import (
    _check_positive_fields,
    _check_range,
    _check_types,
)

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

#: With the remedy's wheel-floor pairs (``sim.floor_impedance`` > 0) the builder sets
#: MuJoCo's ``impratio`` from the pairs' impedance, so ``sim.impratio`` is not used.
PAIRS_SET_IMPRATIO: tuple[str, ...] = ("sim.impratio",)

#: The remedy's pair settings in :class:`SimParams`, unused by a robot whose floor contact
#: has its own settings (the disc's, the roller robots' own ``floor_impedance``) or none.
SIM_PAIR_FIELDS: tuple[str, ...] = ("sim.floor_impedance", "sim.floor_dampratio")


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
        floor_impedance: impedance ``d`` of the wheels' explicit floor pairs
            (:func:`wmr_mujoco.models.builders.common.wheel_floor_pairs`, the remedy of
            ``docs/floor-contact.md``) for robots whose scene adds them; 0: the wheels
            touch the floor through contact bits with the collision class's contact.
            0 or in [1e-4, 0.01]. (The disc, omni3 and mecanum4 carry their own
            ``floor_impedance``.)
        floor_dampratio: damping ratio ζ of the remedy's floor pairs (``solref[1]``), in
            [0.1, 1]. MuJoCo's contact damping depends on the time constant alone and its
            stiffness on ``ζ t_c``: below 1 the pair rests ``(1 − d) g ζ² t_c²`` deep at
            the same damping, so at the same stable ``t_c``.

    """

    timestep: float = 0.002
    contact_timeconst: float = 0.004
    impratio: float = 10.0
    friction: float = 1.0
    floor_impedance: float = 0.0
    floor_dampratio: float = 1.0

    def __post_init__(self) -> None:
        _check_types(self)
        _check_range(self, "timestep", 0.0, 0.02)
        _check_range(self, "contact_timeconst", 0.0, 0.1)
        _check_range(self, "impratio", 1.0, 1000.0, low_inclusive=True)
        _check_range(self, "friction", 0.0, 10.0)
        if self.floor_impedance != 0.0:
            _check_range(self, "floor_impedance", 1e-4, 0.01, low_inclusive=True)
        _check_range(self, "floor_dampratio", 0.1, 1.0, low_inclusive=True)
