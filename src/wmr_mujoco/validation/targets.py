"""Targets, metrics and report rows.

A :class:`Target` is a **requirement** (a number the project was asked for), a **derived
bound** (a number that follows from the physics, with its derivation beside it), or an
**open** requirement (:meth:`Target.open`: asked for, but no model of the package meets it
yet; the row shows the target, the measured figure and the reason, and is counted as open
rather than judged, so that a run passes only if every judged target passes while the
miss stays visible); a metric without a target is reported, not judged.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import NamedTuple, overload

import numpy as np


@dataclass(frozen=True)
class Target:
    """A bound on a metric's magnitude, and where it comes from.

    Attributes:
        value: the bound (``|value| <= bound`` passes), in the metric's unit.
        kind: ``"requirement"`` or ``"derived bound"``.
        basis: the source of a requirement, or the derivation of a derived bound.
    """

    value: float
    kind: str
    basis: str

    KINDS = ("requirement", "derived bound", "open")

    def __post_init__(self) -> None:
        if self.kind not in self.KINDS:
            raise ValueError(f"Target.kind = {self.kind!r}; valid kinds are {self.KINDS}")
        if not (np.isfinite(self.value) and self.value > 0):
            raise ValueError(f"Target.value = {self.value!r}; must be a finite number > 0")

    @classmethod
    def requirement(cls, value: float, source: str) -> Target:
        """A required bound, with where it was asked for."""
        return cls(value, "requirement", source)

    @classmethod
    def derived(cls, value: float, derivation: str) -> Target:
        """A bound derived from the physics, with its derivation."""
        return cls(value, "derived bound", derivation)

    @classmethod
    def open(cls, value: float, source: str, reason: str) -> Target:
        """A requirement no model meets yet: shown with its figure, counted, not judged.

        Args:
            value: the required bound.
            source: where it was asked for (e.g. the issue).
            reason: why it is missed (what the model leaves out).
        """
        return cls(value, "open", f"{source}; not yet met: {reason}")

    def opened(self, reason: str) -> Target:
        """The same bound as an open target (value and basis kept), with why it is missed.

        For a scenario whose family's worst members miss it
        (``Scenario.open_targets``).
        """
        return Target(self.value, "open", f"{self.basis}; not yet met: {reason}")

    @property
    def judged(self) -> bool:
        """Whether a row with this target decides pass or fail (not an open target)."""
        return self.kind != "open"

    @property
    def label(self) -> str:
        """``"requirement: source"`` or ``"derived bound: derivation"``."""
        return f"{self.kind}: {self.basis}"


class Metric(NamedTuple):
    """One measured quantity (``target`` None: reported, not judged)."""

    name: str
    value: float
    unit: str
    target: Target | None = None
    note: str = ""


@dataclass(frozen=True)
class Row:
    """One metric of one scenario, judged.

    ``passed`` None: not judged; ``open``: an open target, its figure shown against it.
    """

    robot: str
    scenario: str
    metric: str
    value: float
    unit: str
    target: float | None = None
    passed: bool | None = None
    note: str = ""
    basis: str = ""
    open: bool = False

    @staticmethod
    def of(robot: str, scenario: str, m: Metric) -> Row:
        """The row of a metric: passes when ``|value| <= target`` (and is finite).

        An open target's row is not judged (``passed`` None, ``open`` True).
        """
        t = m.target
        meets = t is not None and bool(np.isfinite(m.value) and abs(m.value) <= t.value)
        passed = None if t is None or not t.judged else meets
        return Row(robot, scenario, m.name, float(m.value), m.unit,
                   None if t is None else t.value, passed, m.note,
                   "" if t is None else t.label, open=t is not None and not t.judged)

    @property
    def verdict(self) -> str:
        """``pass``, ``FAIL``, ``open`` / ``open (met)``, or empty (reported only)."""
        if self.open:
            meets = np.isfinite(self.value) and self.target is not None and abs(
                self.value) <= self.target
            return "open (met)" if meets else "open"
        return "" if self.passed is None else ("pass" if self.passed else "FAIL")


@overload
def row_value(rows: Sequence[Row], metric: str, unit: str) -> float | None: ...


@overload
def row_value(rows: Sequence[Row], metric: str, unit: str, default: float) -> float: ...


def row_value(rows: Sequence[Row], metric: str, unit: str,
              default: float | None = None) -> float | None:
    """The value of the first row named ``metric`` in ``unit`` (``default`` if none)."""
    return next((r.value for r in rows if r.metric == metric and r.unit == unit), default)
