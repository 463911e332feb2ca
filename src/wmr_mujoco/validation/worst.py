"""A family is judged by its worst member; its spread is reported beside.

Every member of a scenario's family (:mod:`wmr_mujoco.validation.family`) is measured like
a single run, giving one row per metric (:class:`~wmr_mujoco.validation.targets.Row`).
The family's row of a metric is the **worst** member's: the largest ``|value| / target``
(a non-finite value is the worst of all; a metric without a target: the largest
``|value|``). A judged metric passes only if it passes in every member, so one failing
member fails the scenario; an open target shows its worst figure. :func:`spreads` gives,
per metric, the figures of all members: N, median, 10th and 90th percentiles, min, max
and the worst.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.validation.family import describe
from wmr_mujoco.validation.targets import Row


def badness(row: Row) -> float:
    """How bad one row is: ``|value| / target`` (``|value|`` without one; inf if not finite)."""
    if not math.isfinite(row.value):
        return math.inf
    return abs(row.value) / row.target if row.target else abs(row.value)


def _keyed(members: Sequence[Sequence[Row]]) -> dict[tuple[str, str], list[tuple[int, Row]]]:
    """Rows by ``(metric, unit)``, first-seen order, each with its member's index."""
    out: dict[tuple[str, str], list[tuple[int, Row]]] = {}
    for i, rows in enumerate(members):
        for r in rows:
            out.setdefault((r.metric, r.unit), []).append((i, r))
    return out


def worst_rows(members: Sequence[Sequence[Row]], draws: Sequence[Mapping[str, float]]
               ) -> list[Row]:
    """One row per metric: the worst member's, judged over every member.

    ``passed`` is False if any member failed the metric (None: not judged in any); the
    note names the worst member's draw and the number of members.

    Raises:
        ValueError: ``members`` and ``draws`` differ in length.
    """
    if len(members) != len(draws):
        raise ValueError(f"{len(members)} members' rows and {len(draws)} draws")
    if len(members) == 1:
        return list(members[0])
    out = []
    for rows in _keyed(members).values():
        i, worst = max(rows, key=lambda ir: badness(ir[1]))
        judged = [r.passed for _, r in rows if r.passed is not None]
        passed = None if not judged else all(judged)
        note = f"worst of {len(rows)}: {describe(draws[i])}"
        out.append(dataclasses.replace(worst, passed=passed,
                                       note=f"{note}; {worst.note}" if worst.note else note))
    return out


def worst_member(members: Sequence[Sequence[Row]]) -> int:
    """Index of the member whose headline row (its first judged metric) is the worst.

    A member that failed outright (any row failed) comes first; 0 for an empty family.
    """
    def key(i: int) -> tuple[bool, float]:
        rows = members[i]
        judged = [r for r in rows if r.target is not None and not r.open]
        return (any(r.passed is False for r in rows),
                badness(judged[0]) if judged else -math.inf)

    return max(range(len(members)), key=key, default=0)


@dataclass(frozen=True)
class Spread:
    """One metric over a family's members.

    Attributes:
        metric: the metric's name.
        unit: its unit.
        values: each member's value (NaN where a member did not give it), in draw order.
        target: the bound (None: reported, not judged).
        open: the target is an open one.
        passed: every member passes (None: not judged).
    """

    metric: str
    unit: str
    values: tuple[float, ...]
    target: float | None
    open: bool
    passed: bool | None

    @property
    def n(self) -> int:
        """Number of members."""
        return len(self.values)

    def _finite(self) -> np.ndarray:
        v = np.asarray(self.values, float)
        return v[np.isfinite(v)]

    def percentile(self, q: float) -> float:
        """The ``q``-th percentile of the finite values (NaN if none)."""
        v = self._finite()
        return float(np.percentile(v, q)) if v.size else math.nan

    @property
    def median(self) -> float:
        """Median of the finite values."""
        return self.percentile(50.0)

    @property
    def worst(self) -> float:
        """The value of largest ``|value|`` (a non-finite one if any)."""
        bad = [v for v in self.values if not math.isfinite(v)]
        if bad:
            return bad[0]
        return max(self.values, key=abs) if self.values else math.nan

    @property
    def low(self) -> float:
        """Smallest finite value."""
        v = self._finite()
        return float(v.min()) if v.size else math.nan

    @property
    def high(self) -> float:
        """Largest finite value."""
        v = self._finite()
        return float(v.max()) if v.size else math.nan


def spreads(members: Sequence[Sequence[Row]]) -> list[Spread]:
    """Every metric over the members (first-seen order)."""
    out = []
    for (metric, unit), rows in _keyed(members).items():
        values = [math.nan] * len(members)
        for i, r in rows:
            values[i] = r.value
        judged = [r.passed for _, r in rows if r.passed is not None]
        first = rows[0][1]
        out.append(Spread(metric, unit, tuple(values), first.target, first.open,
                          None if not judged else all(judged)))
    return out
