"""Linearising the simulator's own step map by finite differences.

For a state ``x = (q, q̇)`` in MuJoCo's tangent space (quaternions as rotation vectors),
one ``mj_step`` is a map ``x⁺ = Φ(x)``; about a point ``x*`` its linearisation is

    δx⁺ = A δx,    A_ij = (Φ_i(x* + ε e_j) ⊖ Φ_i(x* − ε e_j)) / 2ε

(centred differences, error O(ε²)). An eigenvalue ``μ`` of ``A`` belongs to a continuous
eigenvalue ``s = log(μ) / Δt`` of the simulated dynamics: exact for the integrator's map,
and within the integrator's discretisation error of the continuous system's. The modes of
a motion (a pendulum's swing, a bicycle's weave) are then measured from the physics
itself, without fitting a response.
"""

from __future__ import annotations

import mujoco
import numpy as np

#: Default finite-difference step.
FD_EPS = 1e-6


def step_map(model: mujoco.MjModel, data: mujoco.MjData, eps: float = FD_EPS
             ) -> np.ndarray:
    """``A`` of ``δx⁺ = A δx`` about ``data``'s state, by centred finite differences.

    ``mujoco.mjd_transitionFD`` where it applies; MuJoCo 3.17 refuses the RK4 integrator
    there, so for RK4 the same differences are taken with ``mj_step``
    (:func:`step_map_direct`). Shape ``(2 nv + na)²``.
    """
    if model.opt.integrator == mujoco.mjtIntegrator.mjINT_RK4:
        return step_map_direct(model, data, eps)
    n = 2 * model.nv + model.na
    a = np.zeros((n, n))
    mujoco.mjd_transitionFD(model, data, eps, True, a, None, None, None)
    return a


def step_map_direct(model: mujoco.MjModel, data: mujoco.MjData, eps: float = FD_EPS
                    ) -> np.ndarray:
    """Centred finite differences of one ``mj_step`` in the tangent space ``(δq, δq̇)``.

    Column ``j``: ``(x⁺(x + ε e_j) ⊖ x⁺(x − ε e_j)) / 2ε``, positions differenced with
    ``mj_differentiatePos`` (quaternions on their tangent space). Models with actuator
    states are refused.

    Raises:
        ValueError: the model has actuator states (``na > 0``) or ``eps`` is not > 0.
    """
    if model.na:
        raise ValueError(f"model.na = {model.na}; step_map_direct takes models without "
                         "actuator states (valid: na = 0)")
    if not (np.isfinite(eps) and eps > 0):
        raise ValueError(f"eps = {eps!r}; valid range is (0, inf)")
    nv = model.nv
    work = mujoco.MjData(model)
    out = np.zeros((2 * nv, 2 * nv))

    def step_from(k: int, h: float) -> tuple[np.ndarray, np.ndarray]:
        mujoco.mj_copyData(work, model, data)
        if k < nv:
            dq = np.zeros(nv)
            dq[k] = h
            mujoco.mj_integratePos(model, work.qpos, dq, 1.0)
        else:
            work.qvel[k - nv] += h
        mujoco.mj_step(model, work)
        return work.qpos.copy(), work.qvel.copy()

    for k in range(2 * nv):
        qp, vp = step_from(k, eps)
        qm, vm = step_from(k, -eps)
        dq = np.zeros(nv)
        mujoco.mj_differentiatePos(model, dq, 1.0, qm, qp)
        out[:nv, k] = dq / (2.0 * eps)
        out[nv:, k] = (vp - vm) / (2.0 * eps)
    return out


def continuous_eigenvalues(a: np.ndarray, dt: float) -> np.ndarray:
    """``s = log(μ) / Δt`` for the eigenvalues ``μ`` of a one-step map ``a``."""
    return np.log(np.linalg.eigvals(a).astype(complex)) / dt
