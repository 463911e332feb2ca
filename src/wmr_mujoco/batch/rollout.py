"""The ``"rollout"`` backend: C MuJoCo, members stepped by ``mujoco.rollout``'s threads."""

from __future__ import annotations

import os
import time
from collections.abc import Sequence

import numpy as np

from wmr_mujoco.batch.backend import Backend
from wmr_mujoco.sim.engine import get_state
from wmr_mujoco.sim.stepping import SimulationDivergedError, check_healthy
from wmr_mujoco.validation.runner import Prepared


class RolloutBackend(Backend):
    """Threaded ``mujoco.rollout``: bit-identical to ``wmr.simulate`` member by member.

    Every member starts from its own settled state and solver warm start; members
    built from different parameters bring their own ``MjModel`` (``mujoco.rollout``
    takes one model per member when their sizes agree).

    Args:
        nthread: worker threads (None: one per CPU, at most one per member).
    """

    name = "rollout"

    def __init__(self, nthread: int | None = None) -> None:
        if nthread is not None and (isinstance(nthread, bool) or not isinstance(nthread, int)
                                    or nthread < 1):
            raise ValueError(f"nthread = {nthread!r}; give an integer >= 1, or None (one "
                             "per CPU)")
        self.nthread = nthread

    def run(self, preps: Sequence[Prepared]) -> list[np.ndarray]:
        """Each member's states; see :meth:`Backend.run`."""
        import mujoco
        from mujoco import rollout

        models = [p.model for p in preps]
        shared = all(m is models[0] for m in models)
        initial = np.stack([get_state(p.model, p.data) for p in preps])
        warm = np.stack([p.data.qacc_warmstart for p in preps])
        controls = np.stack([p.controls for p in preps])
        nthread = max(1, min(self.nthread or os.cpu_count() or 1, len(preps)))
        datas = [mujoco.MjData(models[0]) for _ in range(nthread)]
        start = time.perf_counter()
        rolled, _ = rollout.rollout(models[0] if shared else models,
                                    datas if nthread > 1 else datas[0], initial, controls,
                                    initial_warmstart=warm, persistent_pool=nthread > 1)
        self.step_seconds = time.perf_counter() - start
        for d in datas:
            check_healthy(models[0], d)
        out = []
        for i, traj in enumerate(rolled):
            states = np.concatenate([initial[i][None], traj])
            if not np.all(np.isfinite(states)):
                raise SimulationDivergedError(f"member {i} of the batch: non-finite states")
            out.append(states)
        return out
