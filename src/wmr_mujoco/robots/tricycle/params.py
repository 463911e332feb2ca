"""The tricycle's parameters."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from wmr_mujoco.models.params.fields import (
    _check_choice,
    _check_positive_fields,
    _check_range,
)
from wmr_mujoco.models.params.parts import (
    PAIRS_SET_IMPRATIO,
    DriveParams,
    SimParams,
    WheelParams,
)


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

    #: Fields its model does not use: ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = (*PAIRS_SET_IMPRATIO,)


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
    #: 2.5 ms: the longest step dividing the control periods at which every target
    #: holds over the families, at the largest ζ that keeps the penetration bound
    #: (``python -m wmr_mujoco.bench.timestep_choice``).
    sim: SimParams = SimParams(timestep=0.0025, contact_timeconst=0.005,
                               floor_impedance=0.001, floor_dampratio=0.6)

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
