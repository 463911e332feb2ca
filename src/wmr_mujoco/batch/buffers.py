"""Contact and constraint buffer sizes for MuJoCo Warp, measured in a short C MuJoCo run.

MuJoCo Warp allocates its contact (``nconmax`` per world, ``naconmax`` in all) and
constraint-row (``njmax`` per world) buffers once. They are sized here from what C MuJoCo
uses on the same model: from each distinct model's settled start, the first member of
that model is stepped :data:`PROBE_STEPS` steps with its own controls and the largest
contact count ``ncon`` and constraint-row count ``nefc`` seen are kept. The buffers are

    nconmax = ceil(MARGIN · max ncon) + SLACK,    njmax = ceil(MARGIN · max nefc) + SLACK.

This is a margin, not a bound: the contacts of a robot on a flat floor change only when
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
        nconmax: contacts per world.
        njmax: constraint rows per world.
        seen_ncon: the largest contact count in the probe runs.
        seen_nefc: the largest constraint-row count in the probe runs.
    """

    nconmax: int
    njmax: int
    seen_ncon: int
    seen_nefc: int


def measure(preps: Sequence[Prepared], steps: int = PROBE_STEPS) -> Buffers:
    """Buffer sizes for these members (one probe run per distinct model).

    Raises:
        ValueError: ``steps < 0``.
    """
    if steps < 0:
        raise ValueError(f"steps = {steps}; must be >= 0")
    seen_ncon = seen_nefc = 0
    probed: set[int] = set()
    for p in preps:
        if id(p.model) in probed:
            continue
        probed.add(id(p.model))
        data = copy.copy(p.data)
        seen_ncon, seen_nefc = max(seen_ncon, data.ncon), max(seen_nefc, data.nefc)
        for ctrl in p.controls[:steps]:
            data.ctrl[:] = ctrl
            mujoco.mj_step(p.model, data)
            seen_ncon, seen_nefc = max(seen_ncon, data.ncon), max(seen_nefc, data.nefc)
    return Buffers(math.ceil(MARGIN * seen_ncon) + SLACK, math.ceil(MARGIN * seen_nefc) + SLACK,
                   seen_ncon, seen_nefc)
