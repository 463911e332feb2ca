"""The rolling disc's parameters: the mounted disc and the free disc."""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import ClassVar

from wmr_mujoco.models.params.fields import (
    _check_choice,
    _check_positive_fields,
    _check_range,
)
from wmr_mujoco.models.params.parts import (
    SIM_PAIR_FIELDS,
    DriveParams,
    SimParams,
    WheelParams,
)

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
    #: 2.5 ms: the longest step dividing the control periods at which every target
    #: holds over the families (``python -m wmr_mujoco.bench.timestep_choice``).
    sim: SimParams = SimParams(timestep=0.0025, contact_timeconst=0.005)
    free_integrator: str = "RK4"
    free_timestep: float = 0.004
    free_rim: float = 0.002
    floor_impedance: float = 0.001
    floor_impratio: float = 1e4

    #: Fields the model does not use (the mount steers through any angle; the free disc's
    #: settings belong to ``disc_free``; ``floor_impratio`` replaces ``sim.impratio``):
    #: ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = ("drive.steer_angle_limit", "free_integrator",
                                         "free_timestep", "free_rim", "sim.impratio",
                                         *SIM_PAIR_FIELDS)

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
        "mount_mass", "sim.timestep", "floor_impedance", "floor_impratio", *SIM_PAIR_FIELDS,
        *(f"drive.{f.name}" for f in fields(DriveParams)))

    @property
    def total_mass(self) -> float:
        """Mass of everything that moves: the disc alone (no mount)."""
        return self.wheel.mass
