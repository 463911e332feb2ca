"""The differential drive's parameters."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from wmr_mujoco.models.params.fields import _check_positive_fields, _check_range
from wmr_mujoco.models.params.parts import (
    PAIRS_SET_IMPRATIO,
    STEERING_FIELDS,
    DriveParams,
    SimParams,
    WheelParams,
)
from wmr_mujoco.models.params.wheeled import (
    _CASTER,
    _DRIVE,
    _WHEEL,
    MAX_REACH,
    BallCasterParams,
    _check_caster_fits,
    _check_chassis_size,
)


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
    #: 2.5 ms: the longest step dividing the control periods at which every target
    #: holds over the families, at the largest ζ that keeps the penetration bound
    #: (``python -m wmr_mujoco.bench.timestep_choice``).
    sim: SimParams = SimParams(timestep=0.0025, contact_timeconst=0.005,
                               floor_impedance=0.001, floor_dampratio=0.5)

    #: Fields the model does not use (no steering): ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = (*STEERING_FIELDS, *PAIRS_SET_IMPRATIO)

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


#: The default parameter set (a module-level singleton for argument defaults).
DIFFDRIVE = DiffDriveParams()
