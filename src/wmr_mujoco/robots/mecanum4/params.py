"""Parameters of the four-mecanum-wheel platform (``mecanum4``), a frozen validated dataclass.

Lengths in metres, masses in kilograms, angles in radians (see :mod:`wmr_mujoco.models.params`).
The roller geometry is derived in ``docs/mecanum.md``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

from wmr_mujoco.models.params import (
    MAX_WHEEL_MASS,
    MAX_WHEEL_RADIUS,
    PAIRS_SET_IMPRATIO,
    STEERING_FIELDS,
    DriveParams,
    SimParams,
    _check_choice,
    _check_count,
    _check_floor_pair,
    _check_mesh_rollers,
    _check_positive_fields,
    _check_range,
    _check_types,
)


@dataclass(frozen=True)
class MecanumParams:
    """Four mecanum wheels on a rectangular chassis, one row of passive rollers each.

    Wheels at ``(±half_length, ±half_track)`` drive along the chassis x axis. Each carries
    ``rollers_per_wheel`` rollers whose axes, at the contact, make the angle
    ``roller_angle`` with the drive direction; the rollers' outer surface follows the
    ideal mecanum profile (``docs/mecanum.md``), i.e. the wheel's cylindrical envelope of
    radius ``wheel_radius``. Layout "O" on the floor (X seen from above): the contact
    roller axis of every wheel is perpendicular to the line from the chassis centre to the
    wheel when ``half_length = half_track``.

    Attributes:
        wheel_radius: R, radius of the cylindrical envelope over the rollers.
        half_length: a, chassis centre to the wheel axles along x.
        half_track: w, chassis centre to the wheel mid-planes along y.
        roller_angle: γ, roller axis at the contact against the drive direction (π/4).
        chassis_mass: chassis mass (a uniform box for its inertia).
        hub_mass: mass of each wheel hub without rollers.
        roller_mass: mass of each roller.
        rollers_per_wheel: n, rollers on each wheel.
        roller_shape: collision primitive of a roller: ``"ellipsoid"`` (osculating the
            ideal profile at the roller middle), ``"profile"`` (convex mesh of the ideal
            profile; only with ``floor_impedance`` 0, see ``_check_mesh_rollers``),
            ``"capsule"`` or ``"sphere"``.
        roller_thickness: radial thickness b of a roller at its middle, as a fraction of R.
        roller_overlap: extra wheel-rotation span of each roller beyond the ``π/n``
            half-span needed for one roller to always touch, as a fraction.
        roller_armature: rotor inertia added to each roller joint, kg·m².
        roller_damping: viscous damping of each roller joint, N·m·s/rad.
        solver: MuJoCo constraint solver, ``"Newton"`` (default), ``"PGS"`` or ``"CG"``.
            PGS solves the dozen contact rows in about half Newton's time but not to
            Newton's solution (it breaks the mirror symmetry of a straight run and
            shortens the traction-limited lag of a step; ``docs/mecanum.md`` §6), so it
            is not the default; the cost table in ``models/mecanum4/README.md``
            measures both.
        jacobian: MuJoCo's constraint Jacobian and Newton Hessian storage, ``"auto"``
            (MuJoCo's choice: sparse from 60 DoF, so sparse here), ``"dense"`` or
            ``"sparse"``. Not a physics parameter (the same equations in another
            storage); :mod:`wmr_mujoco.bench.solver_cost` times each.
        cone: friction cone, ``"elliptic"`` (the default, no pyramidal creep) or
            ``"pyramidal"``. A physics change: the pyramid's ``condim`` 3 square of
            edges lets a tangential force reach ``μ f_n`` along the contact frame's
            axes but only ``μ f_n / √2`` along their diagonals.
        drive: actuator settings (no steering).
        sim: simulation settings.
        floor_impedance: impedance ``d`` of the roller-floor pairs: 0 (the collision
            class's contact) or [1e-4, 0.01], the disc's remedy for a sliding contact that
            lifts its wheel; the default (``docs/floor-contact.md`` § 4).

    Bounds, physical: ``wheel_radius`` at most
    :data:`~wmr_mujoco.models.params.MAX_WHEEL_RADIUS` = 2.5 m and ``hub_mass`` at most
    :data:`~wmr_mujoco.models.params.MAX_WHEEL_MASS` = 1e4 kg (the largest wheels built);
    ``roller_mass`` at most ``hub_mass`` (a roller is a small part of its wheel);
    ``roller_angle`` in [π/12, 5π/12] (at 0 the rollers lock, at π/2 the wheel cannot
    drive along x); ``roller_thickness`` in (0.02, 0.5] (a roller's half-thickness b is
    inside the wheel, b ≤ R/2); ``roller_overlap`` in [0, 1] and a half-span below 60°
    (a longer roller would reach past the wheel's side); ``rollers_per_wheel`` integers
    [6, 24] (the sizes made); ``half_length`` above 1.05 R (the wheels do not touch fore
    and aft); ``half_track`` above the contact track's half-width plus 0.01 m (the wheels
    clear the chassis centre); ``roller_armature`` in [0, 1e-3] kg·m² and
    ``roller_damping`` in [0, 1e-2] N·m·s/rad (a free roller: far above a roller's own
    inertia they would lock it). The chassis mass has no upper bound of its own.
    """

    wheel_radius: float = 0.05
    half_length: float = 0.15
    half_track: float = 0.15
    roller_angle: float = math.pi / 4.0
    chassis_mass: float = 3.0
    hub_mass: float = 0.15
    roller_mass: float = 0.004
    rollers_per_wheel: int = 16
    roller_shape: str = "ellipsoid"
    roller_thickness: float = 0.1
    roller_overlap: float = 0.1
    roller_armature: float = 0.0
    roller_damping: float = 0.0
    solver: str = "Newton"
    jacobian: str = "auto"
    cone: str = "elliptic"
    drive: DriveParams = DriveParams(
        wheel_kv=2.0, wheel_armature=0.004, wheel_torque_limit=3.0, wheel_rate_limit=60.0)
    sim: SimParams = SimParams(timestep=0.00125, contact_timeconst=0.005, floor_dampratio=0.5)
    floor_impedance: float = 0.001

    ROLLER_SHAPES = ("ellipsoid", "profile", "capsule", "sphere")
    SOLVERS = ("Newton", "PGS", "CG")
    JACOBIANS = ("auto", "dense", "sparse")
    CONES = ("elliptic", "pyramidal")
    #: Fields the model does not use (no steering): ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = (*STEERING_FIELDS, "sim.floor_impedance",
                                         *PAIRS_SET_IMPRATIO)

    def __post_init__(self) -> None:
        _check_types(self)  # before any range: a message that names the wrong type
        _check_range(self, "wheel_radius", 0.0, MAX_WHEEL_RADIUS)
        _check_range(self, "hub_mass", 0.0, MAX_WHEEL_MASS)
        _check_positive_fields(self, exclude=("roller_armature", "roller_damping",
                                              "rollers_per_wheel", "roller_overlap",
                                              "floor_impedance"))
        _check_floor_pair(self)
        _check_range(self, "roller_armature", 0.0, 1e-3, low_inclusive=True)
        _check_range(self, "roller_damping", 0.0, 1e-2, low_inclusive=True)
        _check_range(self, "roller_angle", math.pi / 12.0, 5.0 * math.pi / 12.0,
                     low_inclusive=True)
        _check_range(self, "roller_thickness", 0.02, 0.5)
        _check_range(self, "roller_overlap", 0.0, 1.0, low_inclusive=True)
        _check_range(self, "roller_mass", 0.0, self.hub_mass)
        _check_count(self, "rollers_per_wheel", 6, 24)
        _check_choice(self, "roller_shape", self.ROLLER_SHAPES)
        _check_mesh_rollers(self, "profile")
        _check_choice(self, "solver", self.SOLVERS)
        _check_choice(self, "jacobian", self.JACOBIANS)
        _check_choice(self, "cone", self.CONES)
        if self.roller_half_span >= math.pi / 3.0:
            raise ValueError(f"MecanumParams.roller_overlap = {self.roller_overlap!r} gives a "
                             f"roller half-span of {math.degrees(self.roller_half_span):.1f}°; "
                             f"valid half-spans are below 60° (fewer rollers or less overlap)")
        _check_range(self, "half_length", self.wheel_radius * 1.05)
        min_w = self.wheel_half_width + 0.01
        _check_range(self, "half_track", min_w)

    @property
    def roller_half_width(self) -> float:
        """Radial half-thickness b of a roller at its middle: ``roller_thickness · R``."""
        return self.roller_thickness * self.wheel_radius

    @property
    def axis_distance(self) -> float:
        """Distance d = R − b from the wheel axle to a roller axis."""
        return self.wheel_radius - self.roller_half_width

    @property
    def roller_half_span(self) -> float:
        """Half-span φ_m: half of the wheel rotation one roller covers: ``(π/n)(1 + overlap)``."""
        return math.pi / self.rollers_per_wheel * (1.0 + self.roller_overlap)

    @property
    def wheel_half_width(self) -> float:
        """Axial half-extent of the contact track, ``d tan φ_m tan γ``, plus b."""
        return (self.axis_distance * math.tan(self.roller_half_span)
                * math.tan(self.roller_angle) + self.roller_half_width)

    @property
    def total_mass(self) -> float:
        """Chassis, hubs and rollers."""
        return self.chassis_mass + 4 * (self.hub_mass
                                        + self.rollers_per_wheel * self.roller_mass)
