"""omni3_reduced's parameters: omni3's, less the roller fields the lumped wheel ignores."""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import ClassVar

from wmr_mujoco.models.params.parts import PAIRS_SET_IMPRATIO, STEERING_FIELDS, SimParams
from wmr_mujoco.robots.omni3.params import OmniParams


@dataclass(frozen=True)
class OmniReducedParams(OmniParams):
    """omni3's parameters (:class:`~wmr_mujoco.models.params.OmniParams`), same defaults.

    The rollers' count, mass, thickness, overlap and row offset still set the lumped
    wheel's mass, inertia and capsule; their collider shape, hinge damping and armature
    have nothing to act on (``UNUSED``). ``floor_impedance`` sets the capsule pairs'
    remedy (``builder.floor_pairs``), as omni3's sets its roller pairs'.
    """

    UNUSED: ClassVar[tuple[str, ...]] = (*STEERING_FIELDS, "roller_shape", "roller_armature",
                                         "roller_damping", "sim.floor_impedance",
                                         "solver", "jacobian", "cone",
                                         *PAIRS_SET_IMPRATIO)
    #: The step and contact time constant its tests derive their tolerances for (the
    #: capsule pairs' remedy keeps t_c at least ``builder.CAPSULE_PAIR_STEPS`` steps).
    sim: SimParams = SimParams(timestep=0.001, contact_timeconst=0.002)

    @classmethod
    def from_full(cls, params: OmniParams) -> OmniReducedParams:
        """The reduced rung of a full omni3 parameter set (every field copied)."""
        return cls(**{f.name: getattr(params, f.name) for f in fields(params)})
