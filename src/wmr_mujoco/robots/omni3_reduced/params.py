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
                                         "jacobian", "cone", *PAIRS_SET_IMPRATIO)
    #: MuJoCo's CG solver: the cheaper at the same targets (issue 24 § 4). Nine
    #: degrees of freedom and 18 contact rows sliding sideways (the capsules) take
    #: Newton several iterations and line searches a step, each with its Hessian; CG's
    #: iterations are cheaper (`python -m wmr_mujoco.bench.solver_cost --physics`:
    #: the cost ratio and every target kept at the seeds validated, the `Newton` row the
    #: previous default's). :meth:`from_full` copies omni3's solver, as every field.
    solver: str = "CG"
    #: The cheapest step that meets every target (issue 24 § 4, ``docs/floor-contact.md``
    #: § 4): 1.25 ms, ``contact_timeconst`` 2 Δt (MuJoCo's floor; the collision class's
    #: contact, the tests' stiff one), the capsule pairs at ``t_c = 4 Δt`` = 5 ms
    #: (``builder.CAPSULE_PAIR_STEPS``) and ``ζ = 0.9``. The rest depth ``(1 − d) g ζ²
    #: t_c²`` lowers the rolling radius and so the rotations' heading (``wmr validate``:
    #: worst rotate heading 0.73° at 1 ms, 4 ms, ζ = 1; 1.03° at 1.25 ms, ζ = 1, where the
    #: depth is (5/4)² deeper); ζ = 0.9 keeps it 0.81 · 1.5625 = 1.27× the 1 ms depth
    #: (rotate 0.89°). At ζ = 0.8 (the 1 ms depth) some translations settled into a
    #: rocking in which the two driving wheels took turns at no load (their pairs
    #: touching in the elliptic cone's zero-force state): 1.3 % of path lost.
    sim: SimParams = SimParams(timestep=0.00125, contact_timeconst=0.0025,
                               floor_dampratio=0.9)

    @classmethod
    def from_full(cls, params: OmniParams) -> OmniReducedParams:
        """The reduced rung of a full omni3 parameter set (every field copied)."""
        return cls(**{f.name: getattr(params, f.name) for f in fields(params)})
