"""Contact and constraint buffer sizes for MuJoCo Warp, measured in a short C MuJoCo run.

MuJoCo Warp allocates its contact (``nconmax`` per world, ``naconmax`` in all) and
constraint-row (``njmax`` per world) buffers once. They are sized here from what C MuJoCo
uses on the same model: from each distinct model's settled start, the first member of
that model is stepped :data:`PROBE_STEPS` steps with its own controls and the largest
contact count ``ncon`` and constraint-row count ``nefc`` seen are kept. The buffers are

    nconmax = max(ceil(MARGIN · max ncon) + SLACK, P),    njmax = ceil(MARGIN · max nefc) + SLACK,

``P`` the number of geom pairs that may collide (:func:`collision_pairs`): Warp's broadphase
keeps every candidate pair whose bounding boxes overlap in the same buffer as the
contacts, and there may be more such pairs than contacts (a roller near the floor but not
touching it); each pair is a candidate at most once, so ``P`` bounds them.

The contact term is a margin, not a bound: the contacts of a robot on a flat floor change only when
colliders come and go (rollers of omni and mecanum wheels), which the probe sees, but a
later manoeuvre could bring more. Overflow is therefore checked after every chunk of
steps (:mod:`wmr_mujoco.batch.warp`) and raised, never silent.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco

from wmr_mujoco.validation.runner import Prepared

#: Steps of the probe run from the settled start.
PROBE_STEPS = 200
#: Factor on the largest counts seen: room for twice the contacts seen.
MARGIN = 2.0
#: Added to the scaled counts: room for a few colliders that the probe never saw touch.
SLACK = 8


@dataclass(frozen=True)
class Buffers:
    """Per-world buffer sizes and what they were derived from.

    Attributes:
        nconmax: contacts (and broadphase candidates) per world.
        njmax: constraint rows per world.
        seen_ncon: the largest contact count in the probe runs.
        seen_nefc: the largest constraint-row count in the probe runs.
        pairs: the most geom pairs that may collide in any of the models.
    """

    nconmax: int
    njmax: int
    seen_ncon: int
    seen_nefc: int
    pairs: int


def measure(preps: Sequence[Prepared], steps: int = PROBE_STEPS) -> Buffers:
    """Buffer sizes for these members (one probe run per distinct model).

    Raises:
        ValueError: ``steps < 0``.
    """
    if steps < 0:
        raise ValueError(f"steps = {steps}; must be >= 0")
    seen_ncon = seen_nefc = pairs = 0
    probed: set[int] = set()
    for p in preps:
        if id(p.model) in probed:
            continue
        probed.add(id(p.model))
        pairs = max(pairs, collision_pairs(p.model))
        data = copy.copy(p.data)
        seen_ncon, seen_nefc = max(seen_ncon, data.ncon), max(seen_nefc, data.nefc)
        for ctrl in p.controls[:steps]:
            data.ctrl[:] = ctrl
            mujoco.mj_step(p.model, data)
            seen_ncon, seen_nefc = max(seen_ncon, data.ncon), max(seen_nefc, data.nefc)
    return Buffers(max(math.ceil(MARGIN * seen_ncon) + SLACK, pairs),
                   math.ceil(MARGIN * seen_nefc) + SLACK, seen_ncon, seen_nefc, pairs)


def collision_pairs(model: mujoco.MjModel) -> int:
    """Geom pairs that MuJoCo's collision filter lets through, plus the explicit pairs.

    A pair of geoms ``(i, j)`` may collide when ``contype_i & conaffinity_j`` or
    ``contype_j & conaffinity_i`` is non-zero, their bodies are not welded together, the
    body pair is not excluded, and (unless ``filterparent`` is disabled) neither body's
    weld group is the parent of the other's, the world excepted.
    """
    m = model
    filter_parent = not m.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_FILTERPARENT
    excluded = {(int(s) >> 16, int(s) & 0xFFFF) for s in m.exclude_signature}
    weld = m.body_weldid
    parent_weld = weld[m.body_parentid[weld]]
    count = 0
    for i in range(m.ngeom):
        for j in range(i + 1, m.ngeom):
            if not (m.geom_contype[i] & m.geom_conaffinity[j]
                    or m.geom_contype[j] & m.geom_conaffinity[i]):
                continue
            bi, bj = m.geom_bodyid[i], m.geom_bodyid[j]
            wi, wj = weld[bi], weld[bj]
            if wi == wj or (bi, bj) in excluded or (bj, bi) in excluded:
                continue
            if filter_parent and wi and wj and (parent_weld[wi] == wj or parent_weld[wj] == wi):
                continue
            count += 1
    return count + m.npair
