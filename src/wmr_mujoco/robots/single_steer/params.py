"""The single-steer robot's parameters (class (2,1))."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from wmr_mujoco.models.params.parts import DriveParams, SimParams, WheelParams
from wmr_mujoco.models.params.wheeled import _CASTER, _DRIVE, _WHEEL, MAX_REACH, BallCasterParams
from wmr_mujoco.robots.steered import params as steered


@dataclass(frozen=True)
class SingleSteerParams:
    """Class (2,1): one centred steerable driven wheel at the rear, two ball casters ahead.

    Frame: origin on the steering axis at wheel-centre height (the wheel's contact point
    P lies below it). Casters at ``(caster_x, ±caster_y)``. The chassis CoM lies ahead of
    P (``chassis_com_x > 0``): the robot then behaves as a Chaplygin sleigh driven from
    its blade, whose yaw rate decays when it drives forward (see
    :mod:`wmr_mujoco.robots.steered.analytic`).

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

    #: Fields its model does not use: ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = steered.UNUSED

    wheel: WheelParams = _WHEEL
    fork_mass: float = 0.3
    caster: BallCasterParams = _CASTER
    caster_x: float = 0.32
    caster_y: float = 0.14
    chassis_mass: float = 5.0
    chassis_com_x: float = 0.16
    chassis_size: tuple[float, float, float] = (0.4, 0.3, 0.05)
    drive: DriveParams = _DRIVE
    #: 2.5 ms: the longest step dividing the control periods at which every target
    #: holds over the families, at the largest ζ that keeps the penetration bound
    #: (``python -m wmr_mujoco.bench.timestep_choice``).
    sim: SimParams = SimParams(timestep=0.0025, contact_timeconst=0.005,
                               floor_impedance=0.001, floor_dampratio=0.6)

    def __post_init__(self) -> None:
        steered.check(self, lambda p: (
            ("caster_x", p.wheel.radius + p.caster.radius, MAX_REACH),
            ("caster_y", p.caster.radius, MAX_REACH / 2.0),
            ("chassis_com_x", 0.05 * p.caster_x, 0.95 * p.caster_x)))

    @property
    def total_mass(self) -> float:
        """Chassis, fork, wheel and two balls."""
        return self.chassis_mass + self.fork_mass + self.wheel.mass + 2.0 * self.caster.mass


#: The default parameter set (a module-level singleton for argument defaults).
SINGLE_STEER = SingleSteerParams()
