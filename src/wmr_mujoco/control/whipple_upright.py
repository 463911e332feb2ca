"""The Whipple bicycle kept upright by name, and its seeded family (``docs/control.md``).

The runs are :mod:`wmr_mujoco.loop.tasks.upright`'s on the Whipple bicycle's registry
entry (its pushed start, LQR and linear model: :mod:`wmr_mujoco.robots.whipple.lean`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from wmr_mujoco.loop.tasks import upright
from wmr_mujoco.loop.tasks.upright import DURATION, Upright
from wmr_mujoco.robots.whipple.lean import PERIOD, PUSH, PUSH_RANGE, SPEED_RANGE, SPEEDS
from wmr_mujoco.robots.whipple.params import WhippleParams
from wmr_mujoco.robots.whipple.stability import FALLEN

__all__ = ["DURATION", "FALLEN", "PERIOD", "PUSH", "PUSH_RANGE", "SPEEDS", "SPEED_RANGE",
           "Upright", "UprightFamily", "draw", "family", "linear", "physics"]

#: The registry name of the Whipple bicycle.
ROBOT = "whipple"


def physics(speed: float, push: float = PUSH, controlled: bool = True,
            params: WhippleParams | None = None, duration: float = DURATION,
            period: float = PERIOD) -> Upright:
    """:func:`wmr_mujoco.loop.tasks.upright.physics` on the Whipple bicycle."""
    from wmr_mujoco.robots import get_spec

    return upright.physics(get_spec(ROBOT), speed, push, controlled, params, duration, period)


def linear(speed: float, push: float = PUSH, controlled: bool = True,
           params: WhippleParams | None = None, duration: float = DURATION,
           period: float = PERIOD) -> Upright:
    """:func:`wmr_mujoco.loop.tasks.upright.linear` on the Whipple bicycle."""
    from wmr_mujoco.robots import get_spec

    run = upright.linear(get_spec(ROBOT), speed, push, controlled, params, duration, period)
    assert run is not None  # the Whipple entry has its linear model
    return run


def draw(k: int) -> tuple[float, float]:
    """``(speed, push)`` of draw ``k``: uniform in the ranges, push sign drawn."""
    rng = np.random.default_rng(k)
    speed = float(rng.uniform(*SPEED_RANGE))
    push = float(rng.choice([-1.0, 1.0]) * rng.uniform(*PUSH_RANGE))
    return speed, push


@dataclass(frozen=True)
class UprightFamily:
    """Controlled runs over seeded draws.

    Attributes:
        draws: number.
        min_upright: shortest upright time, s, ``(physics, linear)``.
        worst_peak: largest peak lean, rad, ``(physics, linear)``.
        median_peak: median peak lean, rad, ``(physics, linear)``.
    """

    draws: int
    min_upright: tuple[float, float]
    worst_peak: tuple[float, float]
    median_peak: tuple[float, float]


def family(draws: int = 20, params: WhippleParams | None = None) -> UprightFamily:
    """Controlled runs (physics and linear model) over ``draws`` seeded draws.

    Raises:
        ValueError: ``draws`` not an integer in [1, 1000].
    """
    if isinstance(draws, bool) or not isinstance(draws, int) or not 1 <= draws <= 1000:
        raise ValueError(f"draws = {draws!r}; must be an integer in [1, 1000]")
    runs = [(physics(*draw(k), params=params), linear(*draw(k), params=params))
            for k in range(draws)]
    up = np.array([[r.upright_time for r in pair] for pair in runs])
    peak = np.array([[r.peak_lean for r in pair] for pair in runs])
    return UprightFamily(draws, tuple(up.min(0)), tuple(peak.max(0)),
                         tuple(np.median(peak, 0)))
