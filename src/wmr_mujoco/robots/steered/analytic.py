"""Kinematics of the two steered Campion classes, (1,2) and (2,1).

Body twist ``ν = (u, v, r)`` of the reference point O (forward, left, yaw rate) in the
body frame. A centred steerable wheel at body position ``p = (p_x, p_y)``, steered to β,
rolls without slip only if its contact point moves along its plane, direction
``e(β) = (cos β, sin β)``, at its ground speed ``v_w = R θ̇``::

    (u − r p_y,  v + r p_x) = v_w (cos β, sin β).                        (1)

Class (1,2): two centred steerable wheels at ``(±a, 0)`` (front 1, rear 2). The x-rows
of (1) force ``v₁ cos β₁ = v₂ cos β₂`` (the two axle lines meet in one ICR); with wheel 1's
speed as the input::

    v₂ = v₁ cos β₁ / cos β₂,   u = v₁ cos β₁,
    v  = (v₁ sin β₁ + v₂ sin β₂)/2,   r = (v₁ sin β₁ − v₂ sin β₂)/(2a).

The ICR ``(−v/r, u/r)`` is the intersection of the two axle lines (:func:`axle_intersection`).

Class (2,1): one centred steerable driven wheel at O = P and passive ball casters. (1)
fixes P's velocity ``v_w e(β)`` but not the yaw rate: the ICR lies somewhere on the
wheel's axle line, at ``P + (v_w/r) (−sin β, cos β)``. The yaw rate follows from the
angular momentum about P, since the only horizontal external force acts at P (the
balls transmit none; a ball rolling without slip acts on the chassis as a point mass
``(7/5) m_c`` at its centre). With M the mass of the rigid part, c its CoM seen from P
in the body frame, I_P its yaw inertia about P, and I_f the yaw inertia of fork and
wheel (which turn at ψ̇ + β̇), the moment balance about the moving point P,
``d/dt H_P = −M (c × a_P)``, integrates to the generalised momentum::

    p = (I_P + I_f) ψ̇ + I_f β̇ + M v_w (c × e),     c × e = c_x sin β − c_y cos β,
    ṗ = −M v_w ψ̇ (c × e⊥),                          c × e⊥ = c_x cos β + c_y sin β,

the Chaplygin sleigh driven along its blade. For β = 0 and c = (c_x, 0):
``ψ̈ = −M v_w c_x ψ̇ / (I_P + I_f)``: with the CoM ahead of the wheel (c_x v_w > 0) the yaw
rate decays and a steady steering angle gives a straight *crab* motion along ψ + β.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.analytic.checks import as_array, positive


def _rot(psi: float) -> np.ndarray:
    c, s = np.cos(psi), np.sin(psi)
    return np.array([[c, -s], [s, c]])


# ---- class (1,2) -------------------------------------------------------------------

def double_rear_speed(v_front: float, beta_front: float, beta_rear: float) -> float:
    """Rear ground speed ``v₂ = v₁ cos β₁ / cos β₂`` that keeps one ICR.

    Raises:
        ValueError: ``cos β₂ = 0`` (rear wheel across the body axis: no solution).
    """
    c2 = math.cos(beta_rear)
    if abs(c2) < 1e-9:
        raise ValueError(f"beta_rear = {beta_rear!r}; |β₂| must stay below π/2")
    return float(v_front * math.cos(beta_front) / c2)


def double_twist(v_front: float, beta_front: float, beta_rear: float, half_wheelbase: float
                 ) -> np.ndarray:
    """Body twist ``(u, v, r)`` of the midpoint from wheel 1's speed and both steer angles."""
    a = positive("half_wheelbase", half_wheelbase)
    v2 = double_rear_speed(v_front, beta_front, beta_rear)
    s1, s2 = np.sin(beta_front), np.sin(beta_rear)
    return np.array([v_front * np.cos(beta_front), 0.5 * (v_front * s1 + v2 * s2),
                     (v_front * s1 - v2 * s2) / (2.0 * a)])


def axle_intersection(beta_front: float, beta_rear: float, half_wheelbase: float
                      ) -> np.ndarray:
    """Body-frame point where the two wheel axle lines meet (inf if they are parallel).

    Axle line i: ``p_i + t (−sin β_i, cos β_i)`` with ``p₁ = (a, 0)``, ``p₂ = (−a, 0)``.
    """
    a = positive("half_wheelbase", half_wheelbase)
    d1 = np.array([-np.sin(beta_front), np.cos(beta_front)])
    d2 = np.array([-np.sin(beta_rear), np.cos(beta_rear)])
    m = np.column_stack([d1, -d2])
    if abs(np.linalg.det(m)) < 1e-12:
        return np.array([np.inf, np.inf])
    t = np.linalg.solve(m, np.array([-2.0 * a, 0.0]))
    return np.array([a, 0.0]) + t[0] * d1


def double_rates(x: np.ndarray, u: np.ndarray, half_wheelbase: float) -> np.ndarray:
    """``ẋ`` for ``x = (X, Y, ψ, β₁, β₂)``, ``u = (v₁, ω₁, ω₂)`` (speed, steering rates)."""
    x = as_array("x", x, (5,))
    v1, w1, w2 = as_array("u", u, (3,))
    nu = double_twist(v1, x[3], x[4], half_wheelbase)
    return np.concatenate([_rot(x[2]) @ nu[:2], [nu[2], w1, w2]])


# ---- class (2,1) -------------------------------------------------------------------

@dataclass(frozen=True)
class SleighInertia:
    """Mass data of the (2,1) robot seen from the steered wheel's contact point P.

    Attributes:
        mass: M, rigid part: chassis, fork, wheel and balls at ``(7/5) m_c``.
        com: c, CoM of the rigid part from P in the body frame, m.
        yaw_inertia: I_P, yaw inertia of the rigid part about P, kg·m².
        fork_inertia: I_f, yaw inertia of fork and wheel about the steering axis, kg·m².
    """

    mass: float
    com: tuple[float, float]
    yaw_inertia: float
    fork_inertia: float


def single_yaw_rate(momentum: float, v_wheel: float, beta: float, steer_rate: float,
                    inertia: SleighInertia) -> float:
    """``ψ̇ = (p − I_f β̇ − M v_w (c × e)) / (I_P + I_f)``."""
    cx, cy = inertia.com
    cross = cx * np.sin(beta) - cy * np.cos(beta)
    return float((momentum - inertia.fork_inertia * steer_rate - inertia.mass * v_wheel * cross)
                 / (inertia.yaw_inertia + inertia.fork_inertia))


def single_momentum(yaw_rate: float, v_wheel: float, beta: float, steer_rate: float,
                    inertia: SleighInertia) -> float:
    """``p = (I_P + I_f) ψ̇ + I_f β̇ + M v_w (c × e)``: the inverse of :func:`single_yaw_rate`."""
    cx, cy = inertia.com
    cross = cx * np.sin(beta) - cy * np.cos(beta)
    return float((inertia.yaw_inertia + inertia.fork_inertia) * yaw_rate
                 + inertia.fork_inertia * steer_rate + inertia.mass * v_wheel * cross)


def single_rates(x: np.ndarray, u: np.ndarray, inertia: SleighInertia) -> np.ndarray:
    """``ẋ`` for ``x = (X, Y, ψ, β, p)`` and ``u = (v_w, ω)`` (wheel speed, steering rate)."""
    x = as_array("x", x, (5,))
    v, w = as_array("u", u, (2,))
    psi, beta, mom = x[2], x[3], x[4]
    r = single_yaw_rate(mom, v, beta, w, inertia)
    cx, cy = inertia.com
    heading = psi + beta
    return np.array([v * np.cos(heading), v * np.sin(heading), r, w,
                     -inertia.mass * v * r * (cx * np.cos(beta) + cy * np.sin(beta))])


def single_icr(v_wheel: float, beta: float, yaw_rate: float) -> np.ndarray:
    """Body-frame ICR ``P + (v_w/ψ̇)(−sin β, cos β)``: on the wheel's axle line."""
    if yaw_rate == 0:
        return np.array([np.inf, np.inf])
    return (v_wheel / yaw_rate) * np.array([-np.sin(beta), np.cos(beta)])

