"""Parameters of the caster-supported robots: differential drive and the steered classes.

Same conventions as :mod:`wmr_mujoco.models.params` (SI units, radians, frozen dataclasses that
check their ranges in ``__post_init__`` and raise ``ValueError`` naming field, value and
valid range). Wheels reuse :class:`~wmr_mujoco.models.params.WheelParams`; settings reuse
:class:`~wmr_mujoco.models.params.DriveParams` and :class:`~wmr_mujoco.models.params.SimParams`.

A ball caster is a uniform sphere of radius ``r_c`` and mass ``m_c`` on a frictionless
ball joint at its centre::

    I_c = (2/5) m_c r_c²

Rolling without slip on the floor, a ball pushed at its centre by force F accelerates at
``a = F / (m_c + I_c / r_c²) = F / ((7/5) m_c)``: seen from the chassis it is a point mass
``(7/5) m_c`` at its centre (:attr:`BallCasterParams.effective_mass`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

from wmr_mujoco.models.params import (
    STEERING_FIELDS,
    DriveParams,
    SimParams,
    WheelParams,
    _check_positive_fields,
    _check_range,
)

#: Densest engineering metal a caster ball could be made of (tungsten), kg/m³.
MAX_BALL_DENSITY = 2.0e4
#: Largest chassis plate edge, m: a modelling bound, ten times the default robots' size.
MAX_CHASSIS_EDGE = 5.0
#: Largest distance of a wheel or caster from the chassis origin, m (modelling bound,
#: the reach of a 4 m long platform, as :data:`MAX_CHASSIS_EDGE`).
MAX_REACH = 2.0


def _check_chassis_size(obj: object) -> None:
    """Each edge of ``obj.chassis_size`` in (0, :data:`MAX_CHASSIS_EDGE`] m."""
    size = obj.chassis_size  # type: ignore[attr-defined]
    if not all(0.0 < s <= MAX_CHASSIS_EDGE for s in size):
        raise ValueError(f"{type(obj).__name__}.chassis_size = {size!r} is not physical; "
                         f"valid range of each edge is (0, {MAX_CHASSIS_EDGE:g}] m")

#: Wheel, fork and drive shared by the three robots (the tricycle's proven sizes).
_WHEEL = WheelParams(radius=0.08, width=0.03, mass=0.4)
_DRIVE = DriveParams(wheel_kv=10.0, wheel_armature=0.01, wheel_torque_limit=10.0,
                     steer_kp=100.0, steer_kv=0.5, steer_angle_limit=1.4)


@dataclass(frozen=True)
class BallCasterParams:
    """A passive ball caster: a sphere in a socket on the chassis.

    Attributes:
        radius: ball radius r_c, in [0.002, 0.2] m: the sizes ball transfer units are
            made in (2 mm to 200 mm balls).
        mass: ball mass m_c, in (0, ρ_max (4/3) π r_c³] kg: physically at most a solid
            ball of the densest engineering metal, tungsten (:data:`MAX_BALL_DENSITY`).
        rolling_friction: False (default): contact condim 3, sliding friction only, so
            the ball rolls and spins freely. True: condim 6, MuJoCo's torsional and
            rolling friction act too: a torque ``|τ_roll| ≤ μ_r N`` (``μ_r``, m, the
            third ``friction`` coefficient) opposes rolling, giving a steady drag
            ``F = μ_r N / r_c`` on the chassis.

    """

    radius: float = 0.02
    mass: float = 0.05
    rolling_friction: bool = False

    def __post_init__(self) -> None:
        _check_positive_fields(self)
        _check_range(self, "radius", 0.002, 0.2, low_inclusive=True)
        _check_range(self, "mass", 0.0, MAX_BALL_DENSITY * 4.0 / 3.0 * math.pi
                     * self.radius**3)

    @property
    def inertia(self) -> float:
        """Moment of inertia of the uniform ball about any diameter, ``(2/5) m r²``."""
        return 0.4 * self.mass * self.radius**2

    @property
    def effective_mass(self) -> float:
        """Mass the rolling ball adds at its centre, ``m + I/r² = (7/5) m``."""
        return self.mass + self.inertia / self.radius**2


_CASTER = BallCasterParams()


def _check_caster_fits(obj: object, wheel: WheelParams, caster: BallCasterParams) -> None:
    if caster.radius >= wheel.radius:
        raise ValueError(f"{type(obj).__name__}.caster.radius = {caster.radius!r} must be "
                         f"smaller than the wheel radius; valid range is (0, {wheel.radius:g})")


@dataclass(frozen=True)
class DiffDriveParams:
    """Differential drive: two driven wheels on one axle and a ball caster behind.

    Frame: origin at the axle midpoint at wheel-centre height, x forward, y left; the
    left wheel at ``y = +track/2``; the caster at ``x = caster_x`` (< 0, behind).

    Attributes:
        wheel: each driven wheel.
        track: distance b between the wheel centre planes.
        caster: the ball caster.
        caster_x: caster position along x (negative: behind the axle).
        chassis_mass: chassis mass (a plate).
        chassis_com_x: chassis CoM along x; must lie between caster and axle so that
            the weight rests on all three contacts.
        chassis_size: plate edge lengths (x, y, z) for its inertia and picture.
        drive: actuator settings (the steering entries are unused).
        sim: simulation settings.

    Bounds: ``track`` in (w + 0.01, 2] m (wider than a wheel, so the wheels do not
    touch; at most :data:`MAX_REACH`, a modelling bound); ``caster_x`` in
    (-2, -(R + r_c)] m (the ball clears the wheels; :data:`MAX_REACH`);
    ``chassis_com_x`` in (caster_x, 0]: physical, the weight rests on all three contacts
    only with the CoM between caster and axle;
    caster radius below the wheel radius; ``chassis_size`` edges in (0, 5] m
    (:data:`MAX_CHASSIS_EDGE`). Masses: positive, no upper bound of their own.

    """

    wheel: WheelParams = _WHEEL
    track: float = 0.36
    caster: BallCasterParams = _CASTER
    caster_x: float = -0.25
    chassis_mass: float = 5.0
    chassis_com_x: float = -0.08
    chassis_size: tuple[float, float, float] = (0.34, 0.28, 0.05)
    drive: DriveParams = _DRIVE
    sim: SimParams = SimParams(timestep=0.00125, floor_impedance=0.001)

    #: Fields the model does not use (no steering): ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = STEERING_FIELDS

    def __post_init__(self) -> None:
        _check_positive_fields(self, exclude=("caster_x", "chassis_com_x"))
        _check_range(self, "track", self.wheel.width + 0.01, MAX_REACH)
        _check_range(self, "caster_x", -MAX_REACH, -(self.wheel.radius + self.caster.radius))
        _check_range(self, "chassis_com_x", self.caster_x, 0.0)
        _check_caster_fits(self, self.wheel, self.caster)
        _check_chassis_size(self)

    @property
    def total_mass(self) -> float:
        """Chassis, two wheels and the ball."""
        return self.chassis_mass + 2.0 * self.wheel.mass + self.caster.mass


@dataclass(frozen=True)
class SingleSteerParams:
    """Class (2,1): one centred steerable driven wheel at the rear, two ball casters ahead.

    Frame: origin on the steering axis at wheel-centre height (the wheel's contact point
    P lies below it). Casters at ``(caster_x, ±caster_y)``. The chassis CoM lies ahead of
    P (``chassis_com_x > 0``): the robot then behaves as a Chaplygin sleigh driven from
    its blade, whose yaw rate decays when it drives forward (see
    :mod:`wmr_mujoco.analytic.steered`).

    Attributes:
        wheel: the steered driven wheel.
        fork_mass: mass of the steering fork (CoM on the steering axis).
        caster: each ball caster.
        caster_x: caster position ahead of the steering axis.
        caster_y: half the lateral distance between the casters.
        chassis_mass: chassis mass (a plate).
        chassis_com_x: chassis CoM ahead of the steering axis (inside the support
            triangle).
        chassis_size: plate edge lengths (x, y, z).
        drive: actuator settings.
        sim: simulation settings.

    Bounds: ``caster_x`` in (R + r_c, 2] m (the balls clear the wheel;
    :data:`MAX_REACH`); ``caster_y`` in (r_c, 1] m (the two balls do not touch);
    ``chassis_com_x`` in (0.05, 0.95] · caster_x: physical, the CoM inside the support
    triangle with a margin so that no contact unloads; caster radius below the wheel
    radius; ``chassis_size`` edges in (0, 5] m. Masses: positive, no upper bound.

    """

    wheel: WheelParams = _WHEEL
    fork_mass: float = 0.3
    caster: BallCasterParams = _CASTER
    caster_x: float = 0.32
    caster_y: float = 0.14
    chassis_mass: float = 5.0
    chassis_com_x: float = 0.16
    chassis_size: tuple[float, float, float] = (0.4, 0.3, 0.05)
    drive: DriveParams = _DRIVE
    sim: SimParams = SimParams(timestep=0.0015, floor_impedance=0.001)

    def __post_init__(self) -> None:
        _check_positive_fields(self)
        _check_range(self, "caster_x", self.wheel.radius + self.caster.radius, MAX_REACH)
        _check_range(self, "caster_y", self.caster.radius, MAX_REACH / 2.0)
        _check_range(self, "chassis_com_x", 0.05 * self.caster_x, 0.95 * self.caster_x)
        _check_caster_fits(self, self.wheel, self.caster)
        _check_chassis_size(self)

    @property
    def total_mass(self) -> float:
        """Chassis, fork, wheel and two balls."""
        return self.chassis_mass + self.fork_mass + self.wheel.mass + 2.0 * self.caster.mass


@dataclass(frozen=True)
class DoubleSteerParams:
    """Class (1,2): two centred steerable driven wheels on the x axis and a ball caster.

    Frame: origin at the midpoint between the two steering axes, at wheel-centre height;
    wheels at ``x = ±half_wheelbase`` (front wheel 1, rear wheel 2); the caster at
    ``(0, caster_y)``; the chassis CoM at ``(0, chassis_com_y)`` inside the triangle.

    Attributes:
        wheel: each steered driven wheel.
        half_wheelbase: a, distance of each steering axis from the origin.
        fork_mass: mass of each steering fork.
        caster: the ball caster.
        caster_y: lateral caster position (left > 0).
        chassis_mass: chassis mass (a plate).
        chassis_com_y: lateral chassis CoM position, between 0 and ``caster_y``.
        chassis_size: plate edge lengths (x, y, z).
        drive: actuator settings.
        sim: simulation settings.

    Bounds: ``half_wheelbase`` in (R + 0.01, 2] m (the wheels clear the origin;
    :data:`MAX_REACH`); ``caster_y`` in (R + r_c, 2] m (the ball clears the wheels);
    ``chassis_com_y`` in (0.05, 0.9] · caster_y: physical, the CoM inside the support
    triangle with a margin; caster radius below the wheel radius; ``chassis_size`` edges
    in (0, 5] m. Masses: positive, no upper bound.

    """

    wheel: WheelParams = _WHEEL
    half_wheelbase: float = 0.2
    fork_mass: float = 0.3
    caster: BallCasterParams = _CASTER
    caster_y: float = 0.2
    chassis_mass: float = 5.0
    chassis_com_y: float = 0.07
    chassis_size: tuple[float, float, float] = (0.5, 0.3, 0.05)
    drive: DriveParams = _DRIVE
    sim: SimParams = SimParams(timestep=0.0015, floor_impedance=0.001)

    def __post_init__(self) -> None:
        _check_positive_fields(self)
        _check_range(self, "half_wheelbase", self.wheel.radius + 0.01, MAX_REACH)
        _check_range(self, "caster_y", self.wheel.radius + self.caster.radius, MAX_REACH)
        _check_range(self, "chassis_com_y", 0.05 * self.caster_y, 0.9 * self.caster_y)
        _check_caster_fits(self, self.wheel, self.caster)
        _check_chassis_size(self)

    @property
    def total_mass(self) -> float:
        """Chassis, two forks, two wheels and the ball."""
        return self.chassis_mass + 2.0 * (self.fork_mass + self.wheel.mass) + self.caster.mass


#: Default parameter sets (module-level singletons for argument defaults).
DIFFDRIVE = DiffDriveParams()
SINGLE_STEER = SingleSteerParams()
DOUBLE_STEER = DoubleSteerParams()
