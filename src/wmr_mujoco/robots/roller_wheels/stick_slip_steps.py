"""The stick–slip step response's Moreau step, on Python floats, and its time-stepping loop.

:func:`moreau_step` is the one definition of the Moreau step of
:mod:`~wmr_mujoco.robots.roller_wheels.roller_stick_slip` (its module docstring has the
equations): :func:`~wmr_mujoco.robots.roller_wheels.roller_stick_slip.advance` calls it
on arrays, :func:`march` step after step for
:func:`~wmr_mujoco.robots.roller_wheels.roller_stick_slip.step_response`. The elementwise
operations are done on Python floats (IEEE double arithmetic, one rounding per operation,
in the order written), the products of a matrix and a vector with numpy (BLAS): what that
saves is numpy's per-call cost on vectors of 4 and 7 entries (a step is ~30 small
operations). ``tests/robots/roller_wheels/test_stick_slip_steps.py`` checks its floats
against the same equations written on numpy arrays.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from wmr_mujoco.robots.roller_wheels.roller_stick_slip import BoxLcp, RollerPlatform

#: ``one(q̇, ω_cmd, a_x, a_y, guess) -> (q̇⁺, P, s⁺, state, loads, a_x⁺, a_y⁺)``.
MoreauStep = Callable[[list[float], list[float], float, float, tuple[int, ...] | None],
                      tuple[list[float], np.ndarray, np.ndarray, tuple[int, ...], list[float],
                            float, float]]


def moreau_step(platform: RollerPlatform, lcp: BoxLcp, step: float) -> MoreauStep:
    """One Moreau step of ``h_s = step`` of ``platform`` with the contact solve ``lcp``.

    The returned ``one(q, cmd, ax, ay, guess)`` takes the velocities ``q̇ = (u, v, r, ω)``
    and the commanded wheel rates as lists of floats, the previous step's body
    acceleration ``(a_x, a_y)`` and a guess of the contact state, and computes::

        N_i = max(N_0,i + a_x ∂N_i/∂a_x + a_y ∂N_i/∂a_y, 0)      (a wheel lifts off)
        τ_i = clip(k_v (ω_cmd,i − ω_i), ±τ_max)
        q̇_free = q̇ + h_s M⁻¹ (m r v, −m r u, 0, τ)
        P, s⁺ = box LCP of s⁺ = J q̇_free + W P, |P_i| ≤ μ N_i h_s
        q̇⁺ = q̇_free + M⁻¹ Jᵀ P
        a_x⁺ = (u⁺ − u)/h_s − r⁺ v⁺,   a_y⁺ = (v⁺ − v)/h_s + r⁺ u⁺

    and returns ``(q̇⁺, P, s⁺, state, loads, a_x⁺, a_y⁺)`` (``P``, ``s⁺`` arrays).
    """
    jac = platform.jacobian
    jac_t = jac.T
    minv = platform.inverse_mass.tolist()
    step_minv = (step * platform.inverse_mass).tolist()  # h_s M⁻¹ rounded once, per entry
    base, per_ax, per_ay = (v.tolist() for v in platform._transfer)
    mass, kv, tmax = platform.mass, platform.servo_gain, platform.torque_limit
    friction = platform.friction
    solve = lcp.solve_slip

    def one(q: list[float], cmd: list[float], ax: float, ay: float,
            guess: tuple[int, ...] | None
            ) -> tuple[list[float], np.ndarray, np.ndarray, tuple[int, ...], list[float],
                       float, float]:
        # loads: max(x, 0) (never -0.0: base > 0); the clips keep a NaN
        loads = []
        for b, px, py in zip(base, per_ax, per_ay, strict=True):
            x = b + ax * px + ay * py
            loads.append(0.0 if x < 0.0 else x)
        u, v, r = q[0], q[1], q[2]
        forces = [mass * r * v, -mass * r * u, 0.0]
        for c, w in zip(cmd, q[3:], strict=True):
            t = kv * (c - w)
            forces.append(-tmax if t < -tmax else tmax if t > tmax else t)
        qf = [qi + sm * f for qi, sm, f in zip(q, step_minv, forces, strict=True)]
        slip_free = jac @ np.array(qf)
        bounds = [friction * x * step for x in loads]
        p, slip, state = solve(slip_free, slip_free.tolist(), bounds, guess)
        jp = (jac_t @ p).tolist()
        q_new = [a + mi * b for a, mi, b in zip(qf, minv, jp, strict=True)]
        du, dv = (q_new[0] - u) / step, (q_new[1] - v) / step
        return (q_new, p, slip, state, loads, du - q_new[2] * q_new[1],
                dv + q_new[2] * q_new[0])

    return one


def march(platform: RollerPlatform, lcp: BoxLcp, cmd: np.ndarray, total: int,
          per_chunk: int, step: float, settle_tol: float) -> dict[str, list]:
    """Moreau steps from rest; the rows ``step_response`` records (after row 0).

    Up to ``total`` steps, stopping after a whole chunk of ``per_chunk`` steps in which
    every contact sticks and the twist moves by less than ``settle_tol``.

    Returns:
        lists per step: ``time``, ``q`` (twist and wheel rates), ``p`` (impulses),
        ``loads``, ``state``, ``dissipated`` (``−Σ P·s⁺``).

    Raises:
        ValueError: a run that diverges (non-finite state), at its step.
    """
    n = platform.layout.n
    one = moreau_step(platform, lcp, step)
    cmd_l = np.asarray(cmd, float).tolist()
    stick = (0,) * n
    q = [0.0] * (3 + n)
    ax = ay = 0.0
    state: tuple[int, ...] | None = None
    rows: dict[str, list] = {"time": [], "q": [], "p": [], "loads": [], "state": [],
                             "dissipated": []}
    dissipated = 0.0
    k = 0
    while k < total:
        settled = True
        start = np.array(q[:3])
        for _ in range(min(per_chunk, total - k)):
            q, p, slip, state, loads, ax, ay = one(q, cmd_l, ax, ay, state)
            dissipated -= float(p @ slip)
            k += 1
            if not all(map(math.isfinite, q)):
                raise ValueError(f"step_response diverged at t = {k * step:.4f} s")
            settled = settled and state == stick
            rows["time"].append(k * step)
            rows["q"].append(q)
            rows["p"].append(p)
            rows["loads"].append(loads)
            rows["state"].append(state)
            rows["dissipated"].append(dissipated)
        if settled and float(np.max(np.abs(np.array(q[:3]) - start))) < settle_tol:
            break
    return rows
