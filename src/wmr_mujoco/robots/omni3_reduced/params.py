"""omni3_reduced's parameters: omni3's, less the roller fields the lumped wheel ignores."""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import ClassVar

from wmr_mujoco.models.params.parts import PAIRS_SET_IMPRATIO, STEERING_FIELDS, SimParams
from wmr_mujoco.robots.omni3.params import OmniParams


@dataclass(frozen=True)
class OmniReducedParams(OmniParams):
    """omni3's parameters (:class:`~wmr_mujoco.models.params.OmniParams`), own defaults.

    omni3's fields, with its defaults but ``sim`` (below). ``solver`` reaches the model
    (Newton by default: CG is cheaper here but loses a target at some seeds,
    ``python -m wmr_mujoco.bench.solver_cost --physics``, its ``CG`` row).

    The rollers' count, mass, thickness, overlap and row offset still set the lumped
    wheel's mass, inertia and capsule; their collider shape, hinge damping and armature
    have nothing to act on (``UNUSED``). ``floor_impedance`` sets the capsule pairs'
    remedy (``builder.floor_pairs``), as omni3's sets its roller pairs'.
    """

    UNUSED: ClassVar[tuple[str, ...]] = (*STEERING_FIELDS, "roller_shape", "roller_armature",
                                         "roller_damping", "sim.floor_impedance",
                                         "jacobian", "cone", *PAIRS_SET_IMPRATIO)
    #: The cheapest step that meets every target (issue 24 § 4, ``docs/floor-contact.md``
    #: § 4): 1.25 ms, ``contact_timeconst`` 2 Δt (MuJoCo's floor; the collision class's
    #: contact, the tests' stiff one), the capsule pairs at ``t_c = 4 Δt`` = 5 ms
    #: (``builder.CAPSULE_PAIR_STEPS``) and ``ζ = 0.9``. The rest depth ``(1 − d) g ζ²
    #: t_c²`` lowers the rolling radius and so the rotations' heading: at ζ = 1 the
    #: rotations lose their heading target, at ζ = 0.8 and below a translation loses its
    #: position target (the default step's ζ rows of the timestep table there; at ζ = 0.8
    #: some translations settled into a rocking in which the two driving wheels took turns
    #: at no load, their pairs touching in the elliptic cone's zero-force state).
    sim: SimParams = SimParams(timestep=0.00125, contact_timeconst=0.0025,
                               floor_dampratio=0.9)

    @classmethod
    def from_full(cls, params: OmniParams) -> OmniReducedParams:
        """The reduced rung of a full omni3 parameter set (every field copied)."""
        return cls(**{f.name: getattr(params, f.name) for f in fields(params)})
