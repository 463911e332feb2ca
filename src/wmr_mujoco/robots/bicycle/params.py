"""The bicycle's parameters."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from wmr_mujoco.models.params.fields import (
    _check_positive_fields,
)
from wmr_mujoco.models.params.parts import (
    PAIRS_SET_IMPRATIO,
    DriveParams,
    SimParams,
    WheelParams,
)


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

    #: Fields its model does not use: ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = (*PAIRS_SET_IMPRATIO,)


    rear_wheel: WheelParams = WheelParams(radius=0.34, width=0.035, mass=1.8)
    front_wheel: WheelParams = WheelParams(radius=0.34, width=0.035, mass=1.4)
    wheelbase: float = 1.05
    frame_mass: float = 10.0
    fork_mass: float = 1.2
    drive: DriveParams = DriveParams(wheel_kv=200.0, wheel_torque_limit=60.0,
                                     steer_kp=1000.0, steer_kv=8.0)
    #: 2.5 ms: the longest step dividing the control periods at which every target
    #: holds over the families (``python -m wmr_mujoco.bench.timestep_choice``).
    sim: SimParams = SimParams(timestep=0.0025, contact_timeconst=0.005,
                               floor_impedance=0.001)

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
