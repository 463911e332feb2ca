"""The Lie-bracket parking manoeuvre by robot name, swept over ε (``docs/control.md``).

The cycle and its figures are :mod:`wmr_mujoco.loop.tasks.bracket`'s (re-exported here);
:func:`measure` runs it on the ``mujoco`` backend (contact physics) and on the
``kinematic`` backend over seeded draws of ``(v, ω, ψ₀)``, :func:`sweep` over ``ε``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.loop.tasks.bracket import (
    EPSILONS,
    GAIN,
    MAX_EPS,
    PERIOD,
    RATE,
    RATE_RANGE,
    SEGMENT_EXTRA,
    SPEED,
    SPEED_RANGE,
    bracket_error,
    check_eps,
    exact,
    relative_error,
    run_cycle,
    second_order,
)

__all__ = ["EPSILONS", "GAIN", "MAX_EPS", "PERIOD", "RATE", "RATE_RANGE", "SEGMENT_EXTRA",
           "SPEED", "SPEED_RANGE", "BracketRow", "bracket_error", "check_eps", "draw", "exact",
           "measure", "relative_error", "run_cycle", "second_order", "sweep"]


@dataclass(frozen=True)
class BracketRow:
    """One ε of the sweep.

    Attributes:
        eps: the nominal ε.
        exact_net: ``|Δq_exact|`` (planar), m.
        bracket_error: ``|ε² [g₁, g₂] − Δq_exact| / |Δq_exact|`` (second order's error).
        model_error: worst relative error of the kinematic backend over the draws.
        physics_worst: worst relative error of the physics over the draws.
        physics_median: its median.
        physics_heading: worst ``|Δψ|`` of the physics, rad.
        draws: number of draws.
    """

    eps: float
    exact_net: float
    bracket_error: float
    model_error: float
    physics_worst: float
    physics_median: float
    physics_heading: float
    draws: int


def draw(k: int) -> tuple[float, float, float]:
    """``(speed, rate, start heading)`` of draw ``k`` (``default_rng(k)``, uniform)."""
    rng = np.random.default_rng(k)
    return (float(rng.uniform(*SPEED_RANGE)), float(rng.uniform(*RATE_RANGE)),
            float(rng.uniform(-math.pi, math.pi)))


def measure(robot_name: str = "diffdrive", eps: float = 0.3, draws: int = 20,
            params=None) -> BracketRow:
    """The cycle at ``eps`` over ``draws`` seeded ``(v, ω, ψ₀)`` on both backends.

    Raises:
        ValueError: bad ``eps`` or ``draws``, or a robot not driven by ``(v, ω)``.
        SimulationDivergedError: the physics diverged.
    """
    from wmr_mujoco.drive import make

    if isinstance(draws, bool) or not isinstance(draws, int) or not 1 <= draws <= 1000:
        raise ValueError(f"draws = {draws!r}; must be an integer in [1, 1000]")
    check_eps(eps)
    phys = make(robot_name, backend="mujoco", control_period=PERIOD, params=params)
    model = make(robot_name, backend="kinematic", control_period=PERIOD, params=params)
    errs, model_errs, headings = [], [], []
    for k in range(draws):
        speed, rate, psi0 = draw(k)
        net, d, turn = run_cycle(phys, eps, speed, rate, psi0)
        errs.append(relative_error(net, d, turn))
        headings.append(abs(net[2]))
        net_m, d, turn = run_cycle(model, eps, speed, rate, psi0)
        model_errs.append(relative_error(net_m, d, turn))
    return BracketRow(eps, float(np.linalg.norm(exact(eps, eps)[:2])), bracket_error(eps, eps),
                      float(max(model_errs)), float(max(errs)), float(np.median(errs)),
                      float(max(headings)), draws)


def sweep(robot_name: str = "diffdrive", epsilons: Sequence[float] = EPSILONS,
          draws: int = 20) -> list[BracketRow]:
    """:func:`measure` for each ``ε``."""
    return [measure(robot_name, float(e), draws) for e in epsilons]
