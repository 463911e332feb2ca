"""Kinematics of the planar bicycle (lecture §2).

Configuration ``q = (x, y, ψ, φ)``: rear contact point, heading ψ of the body and rear
wheel, steering angle φ of the front wheel relative to the body; wheelbase ℓ.

With the rear-wheel ground speed ``v_r`` and steering rate ω as inputs::

    ẋ = v_r cos ψ,  ẏ = v_r sin ψ,  ψ̇ = v_r tan φ / ℓ,  φ̇ = ω.

With the front-wheel speed ``v_f`` (the lecture's input), ``v_r = v_f cos φ``, so
``ψ̇ = v_f sin φ / ℓ``. The instantaneous centre of rotation lies on the rear axle line at
``ℓ / tan φ`` from the rear contact (to the left for φ > 0).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from wmr_mujoco.analytic.checks import as_array, positive


def rates(q: np.ndarray, u: np.ndarray, wheelbase: float) -> np.ndarray:
    """``q̇`` for ``q = (x, y, ψ, φ)`` and ``u = (v_r, ω)``."""
    q = as_array("q", q, (4,))
    v, omega = as_array("u", u, (2,))
    ell = positive("wheelbase", wheelbase)
    _, _, psi, phi = q
    return np.array([v * np.cos(psi), v * np.sin(psi), v * np.tan(phi) / ell, omega])


def input_fields(q: np.ndarray, wheelbase: float) -> np.ndarray:
    """Columns ``g₁ = (cos ψ, sin ψ, tan φ/ℓ, 0)``, ``g₂ = (0, 0, 0, 1)`` (4×2)."""
    q = as_array("q", q, (4,))
    ell = positive("wheelbase", wheelbase)
    return np.array([[np.cos(q[2]), 0.0], [np.sin(q[2]), 0.0],
                     [np.tan(q[3]) / ell, 0.0], [0.0, 1.0]])


def front_speed_to_rear(v_front: float, steer: float) -> float:
    """Rear-wheel speed ``v_r = v_f cos φ``."""
    return float(v_front * np.cos(steer))


def icr_radius(steer: float, wheelbase: float) -> float:
    """Signed distance of the ICR from the rear contact along the rear axle, ``ℓ / tan φ``.

    Returns ``inf`` for φ = 0 (straight line).
    """
    ell = positive("wheelbase", wheelbase)
    t = np.tan(steer)
    return float("inf") if t == 0.0 else float(ell / t)


#: ``speed(v_in, φ) -> v``: the rear speed from the input channel and the steering angle
#: at each RK4 stage, elementwise over the steps (None: ``v = v_in``).
Speed = Callable[[np.ndarray, np.ndarray], np.ndarray]


def rk4_trajectory(q0: np.ndarray, inputs: np.ndarray, dt: float, wheelbase: float,
                   speed: Speed | None = None) -> np.ndarray | None:
    """Every state of RK4 on :func:`rates` with ``u_k`` held over step k, all at once.

    The floats of :func:`wmr_mujoco.analytic.integrate.rk4_step` step after step: φ̇ = ω
    does not depend on the state, ψ̇ on φ alone and (ẋ, ẏ) on ψ alone, so each
    component's stages are elementwise arithmetic over all steps in the order numpy
    evaluates it there (stage ``x + (Δt/2) k₁``; ``k = v tan φ / ℓ``, ``v cos ψ``) and
    each state the running sum ``x_k + (Δt/6)(((k₁ + 2k₂) + 2k₃) + k₄)`` (``np.cumsum``:
    the same sequential additions). ``speed`` gives the rear speed ``v`` from the input
    and the stage's φ (the tricycle's ``v_L / (1 − k)``).

    Returns:
        (N + 1, 4) states, ``q0`` first; None where a stage, the start or an input is not
        finite or a shape is wrong (the step-by-step integration then says where and why).
    """
    q0, u = np.asarray(q0, float), np.asarray(inputs, float)
    if q0.shape != (4,) or u.ndim != 2 or u.shape[1] != 2 or not (
            np.isfinite(q0).all() and np.isfinite(u).all()):
        return None
    ell = positive("wheelbase", wheelbase)
    half, sixth = 0.5 * dt, dt / 6.0
    v_in, om = u[:, 0], u[:, 1]

    def running(start: float, k: tuple[np.ndarray, ...]) -> np.ndarray:
        return np.cumsum(np.concatenate([[start], sixth * (((k[0] + 2.0 * k[1])
                                                             + 2.0 * k[2]) + k[3])]))

    phi = running(q0[3], (om, om, om, om))
    phis = (phi[:-1], phi[:-1] + half * om, phi[:-1] + half * om, phi[:-1] + dt * om)
    v = tuple(v_in if speed is None else speed(v_in, p) for p in phis)
    rate = tuple(vs * np.tan(p) / ell for vs, p in zip(v, phis, strict=True))
    psi = running(q0[2], rate)
    psis = (psi[:-1], psi[:-1] + half * rate[0], psi[:-1] + half * rate[1],
            psi[:-1] + dt * rate[2])
    out = np.empty((len(u) + 1, 4))
    out[:, 2], out[:, 3] = psi, phi
    stages = [*phis, *psis]
    for j, trig in ((0, np.cos), (1, np.sin)):
        k = tuple(vs * trig(p) for vs, p in zip(v, psis, strict=True))
        out[:, j] = running(q0[j], k)
        stages += [out[:-1, j] + half * k[0], out[:-1, j] + half * k[1],
                   out[:-1, j] + dt * k[2], *k]
    if not (np.isfinite(out).all() and all(np.isfinite(s).all() for s in (*stages, *v))):
        return None
    return out
