"""Many stick–slip step responses marched together: the same floats as one at a time.

:func:`march_many` advances several runs of
:func:`~wmr_mujoco.robots.roller_wheels.stick_slip_steps.march` (each its own platform
and command) in lockstep, the Moreau step of
:func:`~wmr_mujoco.robots.roller_wheels.stick_slip_steps.moreau_step` written on arrays
of all the runs (the module docstring of
:mod:`~wmr_mujoco.robots.roller_wheels.roller_stick_slip` has its equations)::

    N = max(N_0 + a_x ∂N/∂a_x + a_y ∂N/∂a_y, 0),   τ = clip(k_v (ω_cmd − ω), ±τ_max)
    q̇_free = q̇ + h_s M⁻¹ (m r v, −m r u, 0, τ),   s_free = J q̇_free
    P, s⁺ = box LCP (|P_i| ≤ μ N_i h_s),           q̇⁺ = q̇_free + M⁻¹ Jᵀ P

Each elementwise operation is the same IEEE operation in the same order as the scalar
step's; each product of a matrix and a vector is numpy's stacked ``matmul``, which calls
the same BLAS routine per run as the scalar step's ``@`` does once. The contact solve
tries each run's previous contact state for all runs in that state at once (the
scalar solve tries it first too); a run whose guess fails, or the first step, goes
through :meth:`~wmr_mujoco.robots.roller_wheels.roller_stick_slip.BoxLcp.solve_slip`
itself. So every run's rows are those ``march`` gives it
(``tests/robots/roller_wheels/test_stick_slip_batch.py`` checks them to the bit); what
is saved is numpy's per-call cost, paid once per step for all runs instead of per run.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from wmr_mujoco.robots.roller_wheels.roller_stick_slip import BoxLcp, RollerPlatform

#: The contact solve's tolerance (``BoxLcp.solve_slip``'s default, as the scalar step).
TOL = 1e-12


def _mv(mats: np.ndarray, vecs: np.ndarray) -> np.ndarray:
    """``mats[i] @ vecs[i]`` for every run (stacked ``matmul``: one BLAS call per run)."""
    return np.matmul(mats, vecs[:, :, None])[:, :, 0]


class _Sets:
    """Per contact state, the runs' ``−W_FF⁻¹`` and ``W_FB`` stacked (each run's when needed)."""

    def __init__(self, lcps: Sequence[BoxLcp]) -> None:
        from wmr_mujoco.robots.roller_wheels.roller_stick_slip import _states

        self.lcps = lcps
        self.w = np.stack([lcp.w for lcp in lcps])
        #: Every contact state (the scalar solve's order), and each one's index (its code).
        self.states = _states(len(lcps[0].w))
        self.code = {state: i for i, state in enumerate(self.states)}
        self.table = np.array(self.states)
        self._by_state: dict[tuple[int, ...], tuple] = {}

    def get(self, state: tuple[int, ...], who: np.ndarray) -> tuple:
        """The set of ``state``: signs, stacked ``−W_FF⁻¹`` and ``W_FB``, indices.

        The stacks' rows of the runs ``who`` are filled (``BoxLcp._set``, which keeps
        them); other rows may be unset.
        """
        got = self._by_state.get(state)
        if got is None:
            first = self.lcps[0]._set(state)
            count = len(self.lcps)
            neg_inv = None if first.neg_inv is None else np.empty((count,
                                                                   *first.neg_inv.shape))
            w_fa = None if first.w_fa is None else np.empty((count, *first.w_fa.shape))
            got = self._by_state[state] = (np.array(first.signs), neg_inv, w_fa, first.free,
                                           first.bound, first.upper, first.lower,
                                           np.zeros(count, bool))
        have = got[-1]
        if got[1] is not None:
            for r in who[~have[who]].tolist():
                one = self.lcps[r]._set(state)
                got[1][r] = one.neg_inv
                if got[2] is not None:
                    got[2][r] = one.w_fa
        have[who] = True
        return got[:-1]


def _solve(sets: _Sets, runs: np.ndarray, slip_free: np.ndarray, bounds: np.ndarray,
           guesses: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(P, s⁺, states)`` of the active runs ``runs`` (indices into ``sets``).

    States are codes: indices into ``sets.states`` (−1: none, the first step's guess).
    A run whose solve raises (no contact state fits: ``march`` raises there) gets the
    code −1 and NaN impulses.
    """
    count, n = slip_free.shape
    p_all, s_all = np.empty((count, n)), np.empty((count, n))
    codes = np.full(count, -1)
    tried = (guesses >= 0) & np.isfinite(slip_free).all(axis=1)
    alone = np.flatnonzero(~tried).tolist()
    for code in np.unique(guesses[tried]).tolist():
        idx = np.flatnonzero(tried & (guesses == code))
        who = runs[idx]
        signs, neg_inv, w_fa, free, bound, upper, lower = sets.get(sets.states[code], who)
        sf, b = slip_free[idx], bounds[idx]
        p = signs * b
        ok = np.ones(len(idx), bool)
        if neg_inv is not None:
            rhs = sf + 0.0 if bound.size == 0 else sf[:, free] + _mv(w_fa[who], p[:, bound])
            pf = _mv(neg_inv[who], rhs)
            p[:, free] = pf
            ok = ~np.any(np.abs(pf) > b[:, free] * (1.0 + 1e-9) + 1e-15, axis=1)
        s = sf + _mv(sets.w[who], p)
        scale = (TOL * (1.0 + np.max(np.abs(sf), axis=1)))[:, None]
        ok &= np.all(s[:, upper] <= scale, axis=1) & np.all(s[:, lower] >= -scale, axis=1)
        p_all[idx[ok]], s_all[idx[ok]], codes[idx[ok]] = p[ok], s[ok], code
        alone += idx[~ok].tolist()
    for i in alone:  # the scalar solve: its guess first, then every state in order
        guess = sets.states[guesses[i]] if guesses[i] >= 0 else None
        try:
            p_all[i], s_all[i], state = sets.lcps[runs[i]].solve_slip(
                slip_free[i], slip_free[i].tolist(), bounds[i].tolist(), guess)
            codes[i] = sets.code[state]
        except ValueError:
            p_all[i] = s_all[i] = np.nan
    return p_all, s_all, codes


def march_many(platforms: Sequence[RollerPlatform], lcps: Sequence[BoxLcp],
               commands: Sequence[np.ndarray], total: int, per_chunk: int, step: float,
               settle_tol: float) -> list[dict[str, np.ndarray] | None]:
    """:func:`~wmr_mujoco.robots.roller_wheels.stick_slip_steps.march` of every run.

    Run ``i``: ``platforms[i]`` with the contact solve ``lcps[i]`` from rest under
    ``commands[i]``; each stops after its own settled chunk, as ``march`` does.

    Returns:
        per run, ``march``'s rows as arrays (one row per step: ``time``, ``q``, ``p``,
        ``loads``, ``state``, ``dissipated``); None for a run where ``march`` raises (it
        diverged, or no contact state fits).

    Raises:
        ValueError: platforms of different wheel counts.
    """
    count = len(platforms)
    n = platforms[0].layout.n
    if any(p.layout.n != n for p in platforms):
        raise ValueError("march_many: every platform needs the same number of wheels")
    a = {"jac": np.stack([p.jacobian for p in platforms]),
         "minv": np.stack([p.inverse_mass for p in platforms]),
         "step_minv": np.stack([step * p.inverse_mass for p in platforms]),
         "cmd": np.array([np.asarray(c, float) for c in commands]).reshape(count, n),
         "q": np.zeros((count, 3 + n)), "ax": np.zeros(count), "ay": np.zeros(count),
         "start": np.zeros((count, 3)), "runs": np.arange(count),
         "dissipated": np.zeros(count), "settled": np.ones(count, bool)}
    for k, key in enumerate(("base", "per_ax", "per_ay")):
        a[key] = np.stack([p._transfer[k] for p in platforms])
    for key, attr in (("mass", "mass"), ("kv", "servo_gain"), ("tmax", "torque_limit"),
                      ("friction", "friction")):
        a[key] = np.array([getattr(p, attr) for p in platforms])
    sets = _Sets(lcps)
    stick = sets.code[(0,) * n]
    guesses = np.full(count, -1)
    failed: set[int] = set()
    segments: list[tuple[np.ndarray, dict[str, list]]] = []

    def keep(rows: np.ndarray) -> None:  # only these active runs go on (a new segment)
        nonlocal guesses
        for key in a:
            a[key] = a[key][rows]
        guesses = guesses[rows]
        segments.append((a["runs"], {key: [] for key in RECORDED}))

    segments.append((a["runs"], {key: [] for key in RECORDED}))
    k = 0
    while a["runs"].size and k < total:
        a["start"], a["settled"] = a["q"][:, :3].copy(), np.ones(a["runs"].size, bool)
        for _ in range(min(per_chunk, total - k)):
            q, ax, ay, lim = a["q"], a["ax"], a["ay"], a["tmax"][:, None]
            x = a["base"] + ax[:, None] * a["per_ax"] + ay[:, None] * a["per_ay"]
            loads = np.where(x < 0.0, 0.0, x)
            forces = np.empty_like(q)
            forces[:, 0] = a["mass"] * q[:, 2] * q[:, 1]
            forces[:, 1] = -a["mass"] * q[:, 2] * q[:, 0]
            forces[:, 2] = 0.0
            t = a["kv"][:, None] * (a["cmd"] - q[:, 3:])
            forces[:, 3:] = np.where(t < -lim, -lim, np.where(t > lim, lim, t))
            qf = q + a["step_minv"] * forces
            slip_free = _mv(a["jac"], qf)
            bounds = a["friction"][:, None] * loads * step
            p, slip, guesses = _solve(sets, a["runs"], slip_free, bounds, guesses)
            q_new = qf + a["minv"] * _mv(a["jac"].transpose(0, 2, 1), p)
            du, dv = (q_new[:, 0] - q[:, 0]) / step, (q_new[:, 1] - q[:, 1]) / step
            a["ax"] = du - q_new[:, 2] * q_new[:, 1]
            a["ay"] = dv + q_new[:, 2] * q_new[:, 0]
            a["q"] = q_new
            a["dissipated"] = a["dissipated"] - np.matmul(p[:, None, :], slip[:, :, None])[:, 0, 0]
            k += 1
            good = np.isfinite(q_new).all(axis=1) & (guesses >= 0)
            state = sets.table[guesses]
            a["settled"] &= guesses == stick
            record = segments[-1][1]
            for key, value in (("time", k * step), ("q", q_new), ("p", p), ("loads", loads),
                               ("state", state), ("dissipated", a["dissipated"])):
                record[key].append(value)
            if not good.all():  # march raises here: the run is left out
                failed.update(a["runs"][~good].tolist())
                keep(np.flatnonzero(good))
                if not a["runs"].size:
                    break
        moved = np.max(np.abs(a["q"][:, :3] - a["start"]), axis=1)
        going = ~(a["settled"] & (moved < settle_tol))
        if not going.all():
            keep(np.flatnonzero(going))
    return _per_run(segments, count, failed)


#: What a march records at every step.
RECORDED = ("time", "q", "p", "loads", "state", "dissipated")


def _per_run(segments: list[tuple[np.ndarray, dict[str, list]]], count: int,
             failed: set[int]) -> list[dict[str, np.ndarray] | None]:
    """Each run's rows out of the segments' per-step arrays (runs in each segment's order)."""
    parts: list[dict[str, list]] = [{key: [] for key in RECORDED} for _ in range(count)]
    for runs, record in segments:
        if not record["time"]:
            continue
        stacked = {key: np.stack(record[key], axis=1) for key in RECORDED if key != "time"}
        times = np.array(record["time"])
        for col, r in enumerate(runs.tolist()):
            parts[r]["time"].append(times)
            for key, value in stacked.items():
                parts[r][key].append(value[col])
    return [None if r in failed else {key: np.concatenate(parts[r][key]) for key in RECORDED}
            for r in range(count)]
