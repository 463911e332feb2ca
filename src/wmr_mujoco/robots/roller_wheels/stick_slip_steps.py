"""The stick–slip step response's time-stepping loop: the floats of ``advance``, faster.

:func:`march` runs :func:`~wmr_mujoco.robots.roller_wheels.roller_stick_slip.advance`
step after step (the Moreau step of that module's docstring) and records what
:func:`~wmr_mujoco.robots.roller_wheels.roller_stick_slip.step_response` keeps. It gives
the same floats: every elementwise operation is done on Python floats in the order and
association numpy evaluates it there (IEEE double arithmetic either way: one rounding
per operation), and every product of a matrix and a vector stays the very numpy product
of ``advance`` and :meth:`~wmr_mujoco.robots.roller_wheels.roller_stick_slip.BoxLcp.solve`
(the same BLAS call on the same operands; BLAS may fuse and reorder its sums, which a
Python sum would not). What it saves is numpy's per-call cost on vectors of 4 and 7
entries (a step is ~30 small array operations there), and the twice computed
``s⁺ = s_free + W P``. ``tests/robots/roller_wheels/test_stick_slip_steps.py`` checks the
floats against :func:`advance`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from wmr_mujoco.robots.roller_wheels.roller_stick_slip import BoxLcp, RollerPlatform


def _solver(lcp: BoxLcp, states: Sequence[tuple[int, ...]], tol: float = 1e-12
            ) -> Callable[[np.ndarray, list[float], list[float], tuple[int, ...] | None],
                          tuple[np.ndarray, np.ndarray, tuple[int, ...]]]:
    """:meth:`BoxLcp.solve` with ``s⁺`` returned: ``(P, s⁺, state)``, the same floats.

    Per active set its ``−W_FF⁻¹`` (numpy's ``-a.inv`` there, one negation per entry) is
    kept with the set's index lists.
    """
    w = lcp.w
    cache: dict[tuple[int, ...], tuple] = {}

    def prepared(state: tuple[int, ...]) -> tuple:
        got = cache.get(state)
        if got is None:
            a = lcp._set(state)
            got = (a, [float(s) for s in state], None if a.inv is None else -a.inv,
                   a.free.tolist(), a.upper.tolist(), a.lower.tolist(), a.bound.size == 0)
            cache[state] = got
        return got

    def solve(slip_free: np.ndarray, sf: list[float], bounds: list[float],
              guess: tuple[int, ...] | None) -> tuple[np.ndarray, np.ndarray, tuple[int, ...]]:
        # scale = tol (1 + max|s_free|): the max of the same floats
        scale = tol * (1.0 + max(abs(x) for x in sf))
        for state in (states if guess is None else (guess, *states)):
            a, st, neg_inv, free, upper, lower, all_free = prepared(state)
            p = np.array([si * bi for si, bi in zip(st, bounds, strict=True)])  # st * bounds
            if neg_inv is not None:
                if all_free:  # s_free[F] + W_FB P_B with B empty: + zeros(n)
                    rhs = slip_free + 0.0
                else:
                    rhs = slip_free[a.free] + a.w_fa @ p[a.bound]
                pf = neg_inv @ rhs
                p[a.free] = pf
                if any(abs(x) > bounds[i] * (1.0 + 1e-9) + 1e-15
                       for x, i in zip(pf.tolist(), free, strict=True)):
                    continue
            s = slip_free + w @ p
            sl = s.tolist()
            if all(sl[i] <= scale for i in upper) and all(sl[i] >= -scale for i in lower):
                return p, s, state
        raise ValueError("box_lcp: no contact state satisfies the Coulomb conditions")

    return solve


def march(platform: RollerPlatform, lcp: BoxLcp, states: Sequence[tuple[int, ...]],
          cmd: np.ndarray, total: int, per_chunk: int, step: float, settle_tol: float
          ) -> dict[str, list]:
    """Steps of ``advance`` from rest; the rows ``step_response`` records (after row 0).

    Up to ``total`` steps, stopping after a whole chunk of ``per_chunk`` steps in which
    every contact sticks and the twist moves by less than ``settle_tol``. ``states``:
    the contact states to try, in order (``_states(n)``).

    Returns:
        lists per step: ``time``, ``q`` (twist and wheel rates), ``p`` (impulses),
        ``loads``, ``state``, ``dissipated``.

    Raises:
        ValueError: a run that diverges (non-finite state), at its step.
    """
    n = platform.layout.n
    jac = platform.jacobian
    jac_t = jac.T
    minv = platform.inverse_mass.tolist()
    step_minv = (step * platform.inverse_mass).tolist()  # numpy's step * minv
    base, per_ax, per_ay = (v.tolist() for v in platform._transfer)
    mass, kv, tmax = platform.mass, platform.servo_gain, platform.torque_limit
    friction = platform.friction
    cmd_l = np.asarray(cmd, float).tolist()
    solve = _solver(lcp, states)
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
            # loads: max(base + a_x per_ax + a_y per_ay, 0) (never -0.0: base > 0); the
            # clips keep a NaN, as numpy's maximum and minimum do
            loads = []
            for b, px, py in zip(base, per_ax, per_ay, strict=True):
                x = b + ax * px + ay * py
                loads.append(0.0 if x < 0.0 else x)
            u, v, r = q[0], q[1], q[2]
            forces = [mass * r * v, -mass * r * u, 0.0]
            for c, w in zip(cmd_l, q[3:], strict=True):
                t = kv * (c - w)
                forces.append(-tmax if t < -tmax else tmax if t > tmax else t)
            qf = [qi + sm * f for qi, sm, f in zip(q, step_minv, forces, strict=True)]
            slip_free = jac @ np.array(qf)
            bounds = [friction * x * step for x in loads]
            p, slip, state = solve(slip_free, slip_free.tolist(), bounds, state)
            jp = (jac_t @ p).tolist()
            q_new = [a + mi * b for a, mi, b in zip(qf, minv, jp, strict=True)]
            du, dv = (q_new[0] - u) / step, (q_new[1] - v) / step
            ax, ay = du - q_new[2] * q_new[1], dv + q_new[2] * q_new[0]
            dissipated -= float(p @ slip)
            q = q_new
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
