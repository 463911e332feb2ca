"""The three-omni-wheel robot's parameters: platform, hubs and two rows of rollers."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

from wmr_mujoco.models.params.fields import (
    _check_choice,
    _check_count,
    _check_floor_pair,
    _check_mesh_rollers,
    _check_positive_fields,
    _check_range,
)
from wmr_mujoco.models.params.parts import (
    PAIRS_SET_IMPRATIO,
    STEERING_FIELDS,
    DriveParams,
    SimParams,
)


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
            exact profile; only with ``floor_impedance`` 0, see ``_check_mesh_rollers``),
            ``"ellipsoid"``, ``"capsule"`` or ``"sphere"``.
        roller_thickness: radial thickness of a roller at its middle, as a fraction of r.
        roller_overlap: extra angular span of each roller beyond the ``90°/n`` half-span
            needed for one roller to always touch, as a fraction (the rows overlap).
        row_offset_ratio: axial offset of each row from the wheel mid-plane, as a fraction
            of the roller half-thickness b.
        roller_armature: rotor inertia added to each roller joint, kg·m².
        roller_damping: viscous damping of each roller joint, N·m·s/rad.
        solver: MuJoCo constraint solver, ``"Newton"`` (default), ``"PGS"`` or ``"CG"``
            (each stops at MuJoCo's tolerance or at its iteration limit;
            :mod:`wmr_mujoco.bench.solver_cost` times and validates them).
        jacobian: MuJoCo's constraint Jacobian and Newton Hessian storage, ``"sparse"``
            (the default), ``"dense"`` or ``"auto"`` (MuJoCo's choice: dense below 60
            DoF, so dense for omni3's 45). Not a physics parameter: the same equations in
            another storage (the motion agrees to round-off); sparse is the cheaper at
            this model's sparse mass matrix (a tree of 39 single hinges on one free
            body): :mod:`wmr_mujoco.bench.solver_cost` times each and validates it.
        cone: friction cone, ``"elliptic"`` (the default, no pyramidal creep) or
            ``"pyramidal"``. A physics change: the pyramid's ``condim`` 3 square of
            edges lets a tangential force reach ``μ f_n`` along the contact frame's
            axes but only ``μ f_n / √2`` along their diagonals.
        drive: actuator settings (no steering).
        sim: simulation settings.
        floor_impedance: 0 (contact bits, the collision class's contact) or, in
            [1e-4, 0.01], the impedance ``d`` of explicit roller-floor pairs (and no
            contact bits) with the disc's remedy for a sliding contact that lifts its
            wheel; the default (``docs/floor-contact.md`` § 4).
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
    solver: str = "Newton"
    jacobian: str = "sparse"
    cone: str = "elliptic"
    drive: DriveParams = DriveParams(wheel_kv=2.0, wheel_armature=0.004,
                                     wheel_torque_limit=1.0, wheel_rate_limit=60.0)
    sim: SimParams = SimParams(timestep=0.00125, contact_timeconst=0.00375,
                               floor_dampratio=0.8)
    floor_impedance: float = 0.001

    ROLLER_SHAPES = ("barrel", "ellipsoid", "capsule", "sphere")
    SOLVERS = ("Newton", "PGS", "CG")
    JACOBIANS = ("auto", "dense", "sparse")
    CONES = ("elliptic", "pyramidal")
    #: Fields the model does not use (no steering): ``wmr info`` leaves them out.
    UNUSED: ClassVar[tuple[str, ...]] = (*STEERING_FIELDS, "sim.floor_impedance",
                                         *PAIRS_SET_IMPRATIO)

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
        _check_mesh_rollers(self, "barrel")
        _check_choice(self, "solver", self.SOLVERS)
        _check_choice(self, "jacobian", self.JACOBIANS)
        _check_choice(self, "cone", self.CONES)
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
