"""The batched engines' common shape: a :class:`Backend` checks models, then runs members.

A backend receives every member already prepared (loaded, settled at rest in C MuJoCo,
its open-loop controls scheduled: :class:`~wmr_mujoco.validation.runner.Prepared`) and
returns, per member, the ``mjSTATE_FULLPHYSICS`` state after every step, the settled start
first, exactly as :func:`wmr_mujoco.sim.engine.simulate` does for one run. What is read
from those states (the adapter's pose) is then the same code for every backend.
"""

from __future__ import annotations

import abc
from collections.abc import Sequence
from typing import ClassVar

import mujoco
import numpy as np

from wmr_mujoco.sim.engine import STATE_SPEC
from wmr_mujoco.validation.runner import Prepared


class Backend(abc.ABC):
    """One batched engine.

    Attributes:
        name: what ``simulate_batch(backend=...)`` calls it.
        extra: the pip extra that installs it (None: always installed).
        step_seconds: wall time of the last :meth:`run`'s stepping alone (no set-up, no
            reading back of states), for throughput figures.
    """

    name: ClassVar[str]
    extra: ClassVar[str | None] = None
    step_seconds: float = float("nan")

    @classmethod
    def installed(cls) -> bool:
        """Whether its packages import."""
        return True

    def check(self, robot: str, models: Sequence[mujoco.MjModel]) -> None:  # noqa: B027
        """Refuse, before any work, models this engine cannot run (default: none).

        Raises:
            ValueError: naming the reason and the nearest setting that works.
        """

    @abc.abstractmethod
    def run(self, preps: Sequence[Prepared]) -> list[np.ndarray]:
        """Each member's ``(N + 1, nstate)`` full-physics states, the start first.

        Raises:
            SimulationDivergedError: a member's run diverged (named by its index).
            RuntimeError: the engine ran out of a buffer it was given (named).
        """


def state_segments(model: mujoco.MjModel) -> dict[str, slice]:
    """Where ``time``, ``qpos``, ``qvel`` and ``act`` lie in a full-physics state vector.

    The state is the concatenation, in increasing bit order, of the ``mjtState``
    components in :data:`~wmr_mujoco.sim.engine.STATE_SPEC`.
    """
    spec, start, out = int(STATE_SPEC), 0, {}
    names = {int(mujoco.mjtState.mjSTATE_TIME): "time",
             int(mujoco.mjtState.mjSTATE_QPOS): "qpos",
             int(mujoco.mjtState.mjSTATE_QVEL): "qvel",
             int(mujoco.mjtState.mjSTATE_ACT): "act"}
    bit = 1
    while bit <= spec:
        if spec & bit:
            size = mujoco.mj_stateSize(model, bit)
            if bit in names:
                out[names[bit]] = slice(start, start + size)
            start += size
        bit <<= 1
    return out


def full_states(model: mujoco.MjModel, initial: np.ndarray, qpos: np.ndarray,
                qvel: np.ndarray, act: np.ndarray) -> np.ndarray:
    """Full-physics states from per-step ``qpos``, ``qvel``, ``act`` (``(N + 1, ·)`` each).

    The other components (mocap, user data, plugin state: constant in an open-loop run of
    these robots) are the initial state's; time is ``t_0 + k Δt``.
    """
    seg = state_segments(model)
    states = np.repeat(initial[None], len(qpos), axis=0)
    states[:, seg["time"]] = (initial[seg["time"]][0]
                              + np.arange(len(qpos)) * model.opt.timestep)[:, None]
    states[:, seg["qpos"]] = qpos
    states[:, seg["qvel"]] = qvel
    if act.shape[1]:
        states[:, seg["act"]] = act
    return states
