"""The simulation engines: a Python ``mj_step`` loop, or batched, threaded ``mujoco.rollout``.

Both start from the state (and solver warm start) in ``data`` and return the
``mjSTATE_FULLPHYSICS`` state after every step; they give bit-identical states, so what is
measured from them does not depend on the engine.
"""

from __future__ import annotations

import enum
import os
from collections.abc import Callable, Sequence

import mujoco
import numpy as np

from wmr_mujoco.choices import parse_choice
from wmr_mujoco.sim.stepping import SimulationDivergedError, check_healthy

#: MuJoCo state recorded after every step (what ``mujoco.rollout`` returns).
STATE_SPEC = mujoco.mjtState.mjSTATE_FULLPHYSICS
#: In the Python loop, health is checked every this many steps.
CHECK_EVERY = 5


class Engine(str, enum.Enum):
    """How a simulation is stepped."""

    ROLLOUT = "rollout"
    LOOP = "loop"


def get_state(model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
    """The full physics state of ``data``."""
    state = np.empty(mujoco.mj_stateSize(model, STATE_SPEC))
    mujoco.mj_getState(model, data, state, STATE_SPEC)
    return state


def simulate(model: mujoco.MjModel, data: mujoco.MjData, controls: np.ndarray,
             engine: Engine | str = Engine.ROLLOUT,
             on_step: Callable[[int], None] | None = None) -> np.ndarray:
    """Apply ``controls`` from the state in ``data``; return the state after every step.

    ``engine="loop"`` steps in Python (and calls ``on_step(k)`` after step k, with
    ``data`` live); ``"rollout"`` hands the whole open-loop sequence to
    ``mujoco.rollout`` in C, starting from the same state and solver warm start, so the
    two give bit-identical states. Returns an (N + 1, nstate) array, the initial state
    first.

    Raises:
        ValueError: unknown engine.
        SimulationDivergedError: NaN or MuJoCo warnings.
    """
    engine = parse_choice(Engine, engine, "engine")
    states = np.empty((len(controls) + 1, mujoco.mj_stateSize(model, STATE_SPEC)))
    states[0] = get_state(model, data)
    if engine is Engine.ROLLOUT and on_step is None:
        from mujoco import rollout

        rolled, _ = rollout.rollout(model, data, states[0], controls[None],
                                    initial_warmstart=data.qacc_warmstart.copy()[None])
        states[1:] = rolled[0]
        check_healthy(model, data)
        if not np.all(np.isfinite(states)):
            raise SimulationDivergedError(f"rollout of {len(controls)} steps produced "
                                          f"non-finite states")
        return states
    for k, ctrl in enumerate(controls):
        data.ctrl[:] = ctrl
        mujoco.mj_step(model, data)
        mujoco.mj_getState(model, data, states[k + 1], STATE_SPEC)
        if on_step is not None:
            on_step(k)
        if k % CHECK_EVERY == CHECK_EVERY - 1:
            check_healthy(model, data)
    check_healthy(model, data)
    return states


def simulate_batch(model: mujoco.MjModel, start: mujoco.MjData,
                   controls: Sequence[np.ndarray], nthread: int | None = None
                   ) -> list[np.ndarray]:
    """Simulate several control sequences from one start in one threaded rollout.

    Shorter sequences are padded with their last control and cut afterwards. Each
    trajectory is what :func:`simulate` gives alone, bit for bit.

    Raises:
        SimulationDivergedError: a trajectory has non-finite states (the caller reruns
            the group one by one to say which).
    """
    from mujoco import rollout

    nstep = max(len(c) for c in controls)
    padded = np.stack([np.concatenate([c, np.repeat(c[-1:], nstep - len(c), axis=0)])
                       for c in controls])
    initial = get_state(model, start)
    nthread = max(1, min(nthread or os.cpu_count() or 1, len(controls)))
    datas = [mujoco.MjData(model) for _ in range(nthread)]
    rolled, _ = rollout.rollout(model, datas if nthread > 1 else datas[0],
                                np.tile(initial, (len(controls), 1)), padded,
                                initial_warmstart=np.tile(start.qacc_warmstart,
                                                          (len(controls), 1)),
                                persistent_pool=nthread > 1)
    for d in datas:
        check_healthy(model, d)
    out = []
    for i, (c, traj) in enumerate(zip(controls, rolled, strict=True)):
        states = np.concatenate([initial[None], traj[:len(c)]])
        if not np.all(np.isfinite(states)):
            raise SimulationDivergedError(f"trajectory {i} of the batch: non-finite states")
        out.append(states)
    return out


def simulate_starts(model: mujoco.MjModel, starts: Sequence[mujoco.MjData],
                    controls: Sequence[np.ndarray], nthread: int = 2) -> list[np.ndarray]:
    """Simulate each control sequence from its own start, in one threaded rollout.

    ``starts[i]`` holds trajectory i's initial state and solver warm start (one model for
    all). Shorter sequences are padded with their last control and cut afterwards; each
    trajectory is what :func:`simulate` gives from its start alone, bit for bit.

    Raises:
        ValueError: ``starts`` and ``controls`` differ in length, or are empty.
        SimulationDivergedError: a trajectory has non-finite states (the caller reruns
            the batch one by one to say which).
    """
    from mujoco import rollout

    if len(starts) != len(controls) or not starts:
        raise ValueError(f"{len(starts)} starts and {len(controls)} control sequences; "
                         "give one start per sequence, at least one")
    nstep = max(len(c) for c in controls)
    padded = np.stack([np.concatenate([c, np.repeat(c[-1:], nstep - len(c), axis=0)])
                       for c in controls])
    initial = np.stack([get_state(model, d) for d in starts])
    warm = np.stack([d.qacc_warmstart for d in starts])
    nthread = max(1, min(nthread, len(controls)))
    datas = [mujoco.MjData(model) for _ in range(nthread)]
    rolled, _ = rollout.rollout(model, datas if nthread > 1 else datas[0], initial, padded,
                                initial_warmstart=warm)
    for d in datas:
        check_healthy(model, d)
    out = []
    for i, (c, traj) in enumerate(zip(controls, rolled, strict=True)):
        states = np.concatenate([initial[i][None], traj[:len(c)]])
        if not np.all(np.isfinite(states)):
            raise SimulationDivergedError(f"trajectory {i} of the batch: non-finite states")
        out.append(states)
    return out
