"""The double-steer robot's parameters (class (1,2))."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from wmr_mujoco.models.params.parts import DriveParams, SimParams, WheelParams
from wmr_mujoco.models.params.wheeled import _CASTER, _DRIVE, _WHEEL, MAX_REACH, BallCasterParams
from wmr_mujoco.robots.steered import params as steered


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

    #: Fields its model does not use: ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = steered.UNUSED

    wheel: WheelParams = _WHEEL
    half_wheelbase: float = 0.2
    fork_mass: float = 0.3
    caster: BallCasterParams = _CASTER
    caster_y: float = 0.2
    chassis_mass: float = 5.0
    chassis_com_y: float = 0.07
    chassis_size: tuple[float, float, float] = (0.5, 0.3, 0.05)
    drive: DriveParams = _DRIVE
    sim: SimParams = SimParams(timestep=0.00125, floor_impedance=0.001)

    def __post_init__(self) -> None:
        steered.check(self, lambda p: (
            ("half_wheelbase", p.wheel.radius + 0.01, MAX_REACH),
            ("caster_y", p.wheel.radius + p.caster.radius, MAX_REACH),
            ("chassis_com_y", 0.05 * p.caster_y, 0.9 * p.caster_y)))

    @property
    def total_mass(self) -> float:
        """Chassis, two forks, two wheels and the ball."""
        return self.chassis_mass + 2.0 * (self.fork_mass + self.wheel.mass) + self.caster.mass


#: The default parameter set (a module-level singleton for argument defaults).
DOUBLE_STEER = DoubleSteerParams()
