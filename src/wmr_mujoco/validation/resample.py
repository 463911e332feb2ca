"""A recorded step's data rebuilt from the stored states, without stepping again.

The runner simulates a scenario first (one rollout in C, states only) and measures it
afterwards, every :data:`~wmr_mujoco.validation.traces.RECORD_EVERY`-th step. What a
probe or the lateral-slip measurement reads of step ``k`` is what ``mj_step`` leaves in
``mjData`` after that step: its integration writes the new state
``x_{k+1} = (t_{k+1}, q_{k+1}, q̇_{k+1}, …)``, while the frames, the centres of mass, the
body velocities ``cvel`` and the contacts are those its forward pass computed at the
step's start ``(q_k, q̇_k)``: the configuration whose constraints produced ``q̇_{k+1}``.

:func:`restore_step` rebuilds exactly that from the two stored states, with the stages
of ``mj_forward`` those fields come from (``mj_kinematics``, ``mj_comPos``, ``mj_comVel``,
``mj_collision``) and no constraint solve: the solve already happened in the rollout,
and its result is ``q̇_{k+1}``. The fields are the floats ``mj_step`` leaves, bit for bit
(MuJoCo is the oracle in ``tests/validation/test_resample.py``), at a fraction of a
step's cost; the solver's own outputs (``efc_*``, ``qacc``, contact forces), sensors and
actuator forces are not rebuilt, and nothing here reads them.

That holds for the one-stage integrators (Euler, implicit, implicitfast) of a model
without flexes. RK4 leaves the frames of its last stage, and a flex collides on vertex
positions the kinematics above do not update: for those (:func:`rebuildable` false) the
step is taken again from its stored start (its frames equal the run's to the solver's
tolerance) and then given the stored end state.
"""

from __future__ import annotations

import mujoco
import numpy as np

from wmr_mujoco.sim.engine import STATE_SPEC


def sync_kinematics(model: mujoco.MjModel, data: mujoco.MjData,
                    frames_only: bool = False) -> None:
    """Frames, centres of mass and body velocities of the state in ``data``.

    The stages of ``mj_forward`` that an adapter's ``sim_state`` reads (``mj_kinematics``,
    ``mj_comPos``, ``mj_comVel``: poses, ``mj_objectVelocity``), the same floats as there,
    without the collision and constraint stages it does not read; ``frames_only``: the
    frames alone (an adapter whose ``sim_state`` reads poses and joint positions).
    """
    mujoco.mj_kinematics(model, data)
    if not frames_only:
        mujoco.mj_comPos(model, data)
        mujoco.mj_comVel(model, data)


def rebuildable(model: mujoco.MjModel) -> bool:
    """Whether :func:`restore_step` rebuilds ``mj_step``'s fields exactly for ``model``."""
    return model.opt.integrator != mujoco.mjtIntegrator.mjINT_RK4 and model.nflex == 0


def restore_step(model: mujoco.MjModel, data: mujoco.MjData, start: np.ndarray,
                 end: np.ndarray) -> None:
    """``data`` as ``mj_step`` leaves it, from the step's stored start and end states.

    Args:
        model: the model that produced the states.
        data: overwritten: state ``end``; frames, ``subtree_com``, ``cdof``, ``cvel`` and
            contacts (``ncon``, ``contact``) of ``start``.
        start: the state at the step's start, ``mjSTATE_FULLPHYSICS`` (``STATE_SPEC``).
        end: the state the step produced (same layout).
    """
    if not rebuildable(model):  # step again: the frames of its last stage, the flexes
        mujoco.mj_setState(model, data, start, STATE_SPEC)
        mujoco.mj_step(model, data)
        mujoco.mj_setState(model, data, end, STATE_SPEC)
        return
    mujoco.mj_setState(model, data, start, STATE_SPEC)
    sync_kinematics(model, data)
    mujoco.mj_collision(model, data)
    mujoco.mj_setState(model, data, end, STATE_SPEC)
