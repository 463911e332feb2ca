"""A scenario is a family: what a user would vary, and the seeded draws judged.

A claim about one run is a claim about one draw. A :class:`Family` declares the
quantities a user would vary in a scenario (start phase of the wheels, speeds and
torques, durations, ...), each over a stated range (:class:`Vary`), and how many draws
are judged. :meth:`Family.sample` turns a seed into that many draws, each a mapping
``name -> value``; the same seed always gives the same draws, and a scenario's draws
do not depend on which other scenarios run (the scenario's key enters the seed).

A member of the family is the scenario with its ``draw`` set
(:meth:`~wmr_mujoco.validation.scenarios.Scenario.member`); an empty draw is the
nominal scenario. Whoever runs the member reads the values it varies from
``scenario.draw`` (:meth:`~wmr_mujoco.validation.scenarios.Scenario.value`).
"""

from __future__ import annotations

import math
import zlib
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

#: The seed ``wmr validate`` uses unless told another (CI stays deterministic on it).
DEFAULT_SEED = 0

#: Most draws one family may ask for (a typed-in number may not exhaust memory or time).
MAX_DRAWS = 10_000


@dataclass(frozen=True)
class Vary:
    """One quantity a user would vary, drawn uniformly in ``[low, high]``.

    Attributes:
        name: the quantity, as the scenario's runner reads it from ``scenario.draw``.
        low: smallest value.
        high: largest value (``high == low`` fixes it).
        unit: its unit (``"1"`` for a dimensionless factor).
    """

    name: str
    low: float
    high: float
    unit: str = "1"

    def __post_init__(self) -> None:
        if not self.name:
            raise ValueError("a varied quantity needs a name")
        if not (math.isfinite(self.low) and math.isfinite(self.high) and self.low <= self.high):
            raise ValueError(f"vary {self.name!r}: range [{self.low!r}, {self.high!r}] must be "
                             "finite with low <= high")


@dataclass(frozen=True)
class Family:
    """What a user would vary in a scenario, and how many seeded draws are judged.

    Attributes:
        vary: the varied quantities (names unique).
        draws: number of draws judged (the worst is what is judged).
    """

    vary: tuple[Vary, ...]
    draws: int = 20

    def __post_init__(self) -> None:
        names = [v.name for v in self.vary]
        if len(set(names)) != len(names):
            raise ValueError(f"family varies a quantity twice: {names}")
        if not (isinstance(self.draws, int) and 1 <= self.draws <= MAX_DRAWS):
            raise ValueError(f"draws = {self.draws!r}; must be an integer in 1..{MAX_DRAWS}")

    def sample(self, seed: int, key: str, draws: int | None = None) -> list[dict[str, float]]:
        """``draws`` (default: the family's) seeded draws, each ``{name: value}``.

        The generator is ``numpy.random.default_rng([seed, crc32(key)])``: the same seed
        and scenario key always give the same draws.

        Raises:
            ValueError: ``seed`` not a non-negative integer, or ``draws`` out of range.
        """
        check_seed(seed)
        n = self.draws if draws is None else check_draws(draws)
        rng = np.random.default_rng([int(seed), zlib.crc32(key.encode())])
        values = rng.uniform(size=(n, len(self.vary)))
        return [{v.name: float(v.low + (v.high - v.low) * u)
                 for v, u in zip(self.vary, row, strict=True)} for row in values]


def check_seed(seed: object) -> int:
    """``seed`` as an int, if it is an integer >= 0 (any size).

    Raises:
        ValueError: anything else (a bool, a float, a negative number).
    """
    if isinstance(seed, bool) or not isinstance(seed, int | np.integer) or seed < 0:
        raise ValueError(f"seed = {seed!r}; must be an integer >= 0")
    return int(seed)


def check_draws(draws: object) -> int:
    """``draws`` as an int, if it is an integer in ``1..MAX_DRAWS``.

    Raises:
        ValueError: anything else.
    """
    if isinstance(draws, bool) or not isinstance(draws, int | np.integer) or not (
            1 <= draws <= MAX_DRAWS):
        raise ValueError(f"draws = {draws!r}; must be an integer in 1..{MAX_DRAWS}")
    return int(draws)


def describe(draw: Mapping[str, float]) -> str:
    """One line naming a draw's values, e.g. ``speed=0.274, phase=0.113``."""
    return ", ".join(f"{k}={v:.4g}" for k, v in draw.items()) or "nominal"
