"""Non-holonomy shown numerically: Lie brackets and the net motion of an input cycle.

For a driftless system ``q̇ = Σ g_i(q) u_i`` the Lie bracket
``[f, g](q) = Dg(q) f(q) − Df(q) g(q)`` is the direction the cycle
"f for ε, g for ε, −f for ε, −g for ε" moves the state, to second order:
``Δq = ε² [f, g](q) + O(ε³)``. If the brackets span directions the input fields do
not, the constraints cannot be integrated into ``f(q) = 0`` (Frobenius / Chow): the
system is non-holonomic and can reach any configuration.

Unicycle (disc) ``g₁ = (cos φ, sin φ, 0)`` (roll), ``g₂ = (0, 0, 1)`` (turn):
``[g₁, g₂] = (sin φ, −cos φ, 0)``, sideways. The exact cycle "forward d, turn Δ, back d,
turn back" moves the disc, in its start frame, by ``(d (1 − cos Δ), −d sin Δ)``.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from wmr_mujoco.analytic.checks import as_array, positive
from wmr_mujoco.analytic.integrate import rk4_step

VectorField = Callable[[np.ndarray], np.ndarray]


def jacobian(field: VectorField, q: np.ndarray, h: float = 1e-6) -> np.ndarray:
    """Central-difference Jacobian ``D field(q)`` (error O(h²))."""
    q = as_array("q", q, (None,))
    cols = []
    for i in range(q.size):
        e = np.zeros_like(q)
        e[i] = h
        cols.append((np.asarray(field(q + e)) - np.asarray(field(q - e))) / (2.0 * h))
    return np.stack(cols, axis=1)


def lie_bracket(f: VectorField, g: VectorField, q: np.ndarray, h: float = 1e-6
                ) -> np.ndarray:
    """``[f, g](q) = Dg f − Df g``, with finite-difference Jacobians."""
    q = as_array("q", q, (None,))
    return jacobian(g, q, h) @ np.asarray(f(q)) - jacobian(f, q, h) @ np.asarray(g(q))


def accessibility_rank(fields: Sequence[VectorField], q: np.ndarray, depth: int = 2,
                       tol: float = 1e-6) -> int:
    """Rank of the fields and their iterated brackets up to ``depth`` at ``q``."""
    q = as_array("q", q, (None,))
    level: list[VectorField] = list(fields)
    all_fields = list(fields)
    for _ in range(depth - 1):
        new = []
        for f in level:
            for g in fields:
                new.append(lambda x, f=f, g=g: lie_bracket(f, g, x))
        all_fields += new
        level = new
    mat = np.stack([np.asarray(f(q)) for f in all_fields], axis=1)
    return int(np.linalg.matrix_rank(mat, tol))


def flow(field: VectorField, q: np.ndarray, duration: float, steps: int = 200) -> np.ndarray:
    """Follow ``q̇ = field(q)`` for ``duration`` (negative: backwards) with RK4."""
    q = as_array("q", q, (None,)).copy()
    h = duration / steps
    no_input = np.zeros(0)
    for _ in range(steps):
        q = rk4_step(lambda x, _u: np.asarray(field(x)), q, no_input, h)
    return q


def bracket_cycle_durations(f: VectorField, g: VectorField, q: np.ndarray, t_f: float,
                            t_g: float) -> np.ndarray:
    """State after the cycle f for ``t_f``, g for ``t_g``, then −f, −g as long."""
    for field, duration in ((f, t_f), (g, t_g), (f, -t_f), (g, -t_g)):
        q = flow(field, q, duration)
    return q


def bracket_cycle(f: VectorField, g: VectorField, q: np.ndarray, eps: float) -> np.ndarray:
    """State after the cycle f, g, −f, −g, each for time ``eps`` (``≈ q + ε² [f, g]``)."""
    return bracket_cycle_durations(f, g, q, positive("eps", eps), eps)


def unicycle_cycle_displacement(distance: float, turn: float) -> np.ndarray:
    """Net displacement, in the start frame, of "forward d, turn Δ, back d, turn back".

    Returns ``(d (1 − cos Δ), −d sin Δ)``: a sideways move, forbidden to the disc at
    every instant, made of allowed motions.
    """
    d = float(distance)
    return np.array([d * (1.0 - np.cos(turn)), -d * np.sin(turn)])
