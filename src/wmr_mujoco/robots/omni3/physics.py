"""omni3's physics runs from several starts at once: threaded ``mujoco.rollout`` batches.

A family's members differ in their start (the wheels' phase within a roller pitch) as
well as in their inputs, so each batch here takes one initial state per run:
:func:`settle_at_phases` settles the robot at rest with its wheels turned to each phase,
:func:`rollout_from` runs control sequences from given states. Both check every state
(a diverging run raises, never returns).
"""

from __future__ import annotations

import os
from collections.abc import Sequence

import mujoco
import numpy as np

from wmr_mujoco.sim.engine import STATE_SPEC
from wmr_mujoco.sim.stepping import SimulationDivergedError

#: omni3's wheel hinges (and their actuators), in layout order.
WHEELS = ("wheel1", "wheel2", "wheel3")
#: Threads of a batch (the machine's cores, at most this many).
MAX_THREADS = 2


def _threads(n: int) -> int:
    return max(1, min(MAX_THREADS, os.cpu_count() or 1, n))


def rollout_from(model: mujoco.MjModel, starts: np.ndarray,
                 controls: Sequence[np.ndarray]) -> list[np.ndarray]:
    """Each control sequence (n_k, nu) from its own start (rows of ``starts``).

    Shorter sequences are padded with their last control and cut afterwards.

    Returns:
        per run, its ``(n_k + 1, nstate)`` full-physics states, the start first.

    Raises:
        ValueError: as many starts as control sequences are needed, each sequence
            non-empty.
        SimulationDivergedError: a run has non-finite states.
    """
    from mujoco import rollout

    starts = np.atleast_2d(np.asarray(starts, float))
    if len(starts) != len(controls) or not controls or min(len(c) for c in controls) < 1:
        raise ValueError(f"{len(starts)} starts for {len(controls)} control sequences; "
                         "give one start per non-empty sequence")
    nstep = max(len(c) for c in controls)
    padded = np.stack([np.concatenate([c, np.repeat(c[-1:], nstep - len(c), axis=0)])
                       for c in controls])
    nthread = _threads(len(controls))
    datas = [mujoco.MjData(model) for _ in range(nthread)]
    rolled, _ = rollout.rollout(model, datas if nthread > 1 else datas[0], starts, padded,
                                persistent_pool=nthread > 1)
    out = []
    for i, (c, traj) in enumerate(zip(controls, rolled, strict=True)):
        states = np.concatenate([starts[i][None], traj[:len(c)]])
        if not np.all(np.isfinite(states)):
            raise SimulationDivergedError(f"run {i} of the batch: non-finite states")
        out.append(states)
    return out


def settle_at_phases(model: mujoco.MjModel, wheels: Sequence[str], phases: Sequence[float],
                     settle: float) -> np.ndarray:
    """States of the robot settled at rest for ``settle`` s, its wheels turned by each phase.

    Every wheel hinge starts at ``phase`` (rad) from the model's reference pose and the
    controls stay zero (a rate servo holds the wheels at rest; the start phase is then
    what the run begins from, up to the creep of the wheels under the weight's moment
    while the servo holds them, which the runs read from the settled state).

    Returns:
        (len(phases), nstate) full-physics states.
    """
    data = mujoco.MjData(model)
    nstate = mujoco.mj_stateSize(model, STATE_SPEC)
    starts = np.empty((len(phases), nstate))
    adr = [model.jnt_qposadr[model.joint(w).id] for w in wheels]
    for k, phase in enumerate(phases):
        mujoco.mj_resetData(model, data)
        data.qpos[adr] = phase
        mujoco.mj_getState(model, data, starts[k], STATE_SPEC)
    zero = np.zeros((round(settle / model.opt.timestep), model.nu))
    return np.array([s[-1] for s in rollout_from(model, starts, [zero] * len(phases))])


def contact_wheels(model: mujoco.MjModel, data: mujoco.MjData,
                   wheels: Sequence[str] = WHEELS) -> np.ndarray:
    """The wheel of each current floor contact: (ncon,) indices into ``wheels``.

    A contact belongs to the wheel whose roller (a child body of the wheel) touches the
    ``floor`` in it; −1 for any other contact.
    """
    floor = model.geom("floor").id
    wheel_of = np.full(model.nbody, -1)
    wheel_of[[model.body(w).id for w in wheels]] = np.arange(len(wheels))
    g1, g2 = data.contact.geom1[:data.ncon], data.contact.geom2[:data.ncon]
    other = np.where(g1 == floor, g2, g1)  # the geom that is not the floor
    wheel = wheel_of[model.body_parentid[model.geom_bodyid[other]]]
    return np.where((g1 == floor) | (g2 == floor), wheel, -1)


def wheels_off_floor(model: mujoco.MjModel, states: np.ndarray,
                     wheels: Sequence[str] = WHEELS) -> np.ndarray:
    """(N, len(wheels)) True where no roller of a wheel touches the ``floor``.

    Each full-physics state (rows of ``STATE_SPEC``) is set and its contacts found
    (``mj_fwdPosition``), assigned to wheels by :func:`contact_wheels`.
    """
    data = mujoco.MjData(model)
    out = np.ones((len(states), len(wheels)), dtype=bool)
    for k, state in enumerate(states):
        mujoco.mj_setState(model, data, state, STATE_SPEC)
        mujoco.mj_fwdPosition(model, data)
        touching = contact_wheels(model, data, wheels)
        out[k, touching[touching >= 0]] = False
    return out
