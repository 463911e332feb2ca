"""omni3_reduced's parameters: omni3's, less the roller fields the lumped wheel ignores."""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import ClassVar

from wmr_mujoco.models.params.parts import SIM_PAIR_FIELDS, STEERING_FIELDS, SimParams
from wmr_mujoco.robots.omni3.params import OmniParams


@dataclass(frozen=True)
class OmniReducedParams(OmniParams):
    """omni3's parameters (:class:`~wmr_mujoco.models.params.OmniParams`), same defaults.

    The rollers' count, mass, thickness, overlap and row offset still set the lumped
    wheel's mass, inertia and capsule; their collider shape, hinge damping and armature,
    and the floor-pair remedy have nothing to act on (``UNUSED``).
    """

    UNUSED: ClassVar[tuple[str, ...]] = (*STEERING_FIELDS, "roller_shape", "roller_armature",
                                         "roller_damping", "floor_impedance",
                                         "solver", "jacobian", "cone",
                                         *SIM_PAIR_FIELDS)
    #: Its capsule pairs take the collision class's contact (``builder.floor_pairs``), at
    #: the step and time constant its tests derive their tolerances for (omni3's before
    #: omni3 took the floor pairs' remedy, docs/floor-contact.md).
    floor_impedance: float = 0.0
    sim: SimParams = SimParams(timestep=0.001, contact_timeconst=0.002)

    @classmethod
    def from_full(cls, params: OmniParams) -> OmniReducedParams:
        """The reduced rung of a full omni3 parameter set (every field copied)."""
        return cls(**{f.name: getattr(params, f.name) for f in fields(params)})
