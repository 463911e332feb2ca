"""Inertia about a hinge, read from a compiled model (body inertias and armature)."""

from __future__ import annotations

import mujoco
import numpy as np


def in_subtree(model: mujoco.MjModel, body: int, root: int) -> bool:
    """Whether ``body`` is ``root`` or one of its descendants."""
    while body > 0:
        if body == root:
            return True
        body = int(model.body_parentid[body])
    return body == root


def hinge_inertia(model: mujoco.MjModel, joint: str) -> float:
    """Inertia about a hinge at the model's reference pose: bodies it moves + armature.

    ``J = Σ_b (âᵀ I_b â + m_b |r_b⊥|²) + armature`` over the joint's body and its
    subtree, with ``â`` the joint axis, ``I_b`` the body's inertia about its centre of
    mass in the world frame and ``r_b⊥`` the centre of mass's offset from the axis
    (parallel-axis theorem). The armature is the rotor inertia reflected to the joint,
    which the simulation adds to the joint's diagonal of the mass matrix.

    Raises:
        ValueError: no such joint, or it is not a hinge.
    """
    try:
        jnt = model.joint(joint)
    except KeyError:
        raise ValueError(f"joint = {joint!r}: no such joint in the model") from None
    if jnt.type[0] != mujoco.mjtJoint.mjJNT_HINGE:
        raise ValueError(f"joint = {joint!r} is not a hinge (type {int(jnt.type[0])})")
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    jid = jnt.id
    root = int(jnt.bodyid[0])
    bodies = [b for b in range(model.nbody) if in_subtree(model, b, root)]
    total = inertia_about_axis(model, data, bodies, data.xanchor[jid], data.xaxis[jid])
    return float(total + model.dof_armature[model.jnt_dofadr[jid]])


def inertia_about_axis(model: mujoco.MjModel, data: mujoco.MjData, bodies: list[int],
                       point: np.ndarray, axis: np.ndarray) -> float:
    """Inertia of ``bodies`` about the line through ``point`` along unit ``axis``.

    ``J = Σ_b (âᵀ I_b â + m_b |r_b⊥|²)`` with the frames of ``data`` (after
    ``mj_kinematics``): ``I_b`` about the body's centre of mass in the world frame and
    ``r_b⊥`` its offset from the line (parallel-axis theorem).
    """
    total = 0.0
    for b in bodies:
        rot = data.ximat[b].reshape(3, 3)
        inertia = rot @ np.diag(model.body_inertia[b]) @ rot.T
        r = data.xipos[b] - point
        r_perp = r - axis * (r @ axis)
        total += axis @ inertia @ axis + model.body_mass[b] * (r_perp @ r_perp)
    return float(total)


def inertia_tensor_about(model: mujoco.MjModel, data: mujoco.MjData, bodies: list[int],
                         point: np.ndarray) -> np.ndarray:
    """Composite 3×3 inertia of ``bodies`` about ``point``, world frame.

    ``I = Σ_b (I_b + m_b (|r_b|² 1 − r_b r_bᵀ))`` with the frames of ``data`` (after
    ``mj_kinematics``): ``I_b`` about the body's centre of mass in the world frame and
    ``r_b`` its offset from ``point`` (parallel-axis theorem); ``âᵀ I â`` is
    :func:`inertia_about_axis`.
    """
    total = np.zeros((3, 3))
    for b in bodies:
        rot = data.ximat[b].reshape(3, 3)
        r = data.xipos[b] - point
        total += (rot @ np.diag(model.body_inertia[b]) @ rot.T
                  + model.body_mass[b] * ((r @ r) * np.eye(3) - np.outer(r, r)))
    return total
