"""Units of work of ``wmr validate``: a family alone, or a robot's families prepared together.

A robot whose ``prepare`` batches its measurement members
(:attr:`~wmr_mujoco.validation.spec.RobotSpec.prepare`) may name the families whose members
are best batched all at once (:attr:`~wmr_mujoco.validation.spec.RobotSpec.prepared_together`:
runs of one length, whose batched model costs per step, not per run). Those families are
one unit: one process prepares all their members in one call, then runs each family,
whose own ``prepare`` finds its members ready. Every other family is a unit of its own.
Each family's result is what it gives alone (a member's run does not depend on the
batch it was simulated in); its ``seconds`` are its own wall time and an equal share
of the unit's prepare.
"""

from __future__ import annotations

import time
import traceback
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from wmr_mujoco.validation.runner import Job, ScenarioResult


def units(work: Sequence[Job]) -> list[list[int]]:
    """Indices of ``work`` in units, each unit in declared order, units by first index.

    The families of one robot spec named in its ``prepared_together`` form one unit
    (where there are two or more of them); every other family is a unit of its own.
    """
    out: list[list[int]] = []
    together: dict[int, list[int]] = {}  # id(spec) -> its unit
    for i, (spec, s) in enumerate(work):
        if s.family is not None and s.name in spec.prepared_together:
            unit = together.get(id(spec))
            if unit is not None:
                unit.append(i)
                continue
            together[id(spec)] = [i]
            out.append(together[id(spec)])
        else:
            out.append([i])
    return out


def unit_hint(work: Sequence[Job], unit: Sequence[int],
              hints: Mapping[str, float]) -> float | None:
    """Seconds of a unit in an earlier run: the sum of its families' (None: one unknown)."""
    keys = [work[i][1].key for i in unit]
    return sum(hints[k] for k in keys) if all(k in hints for k in keys) else None


def run_unit(work: Sequence[Job], unit: Sequence[int], seed: int, draws: int | None,
             progress: Callable[[str], None] | None = None
             ) -> list[tuple[int, ScenarioResult]]:
    """Run the families of one unit; ``(index, result)`` per family, in the unit's order.

    A unit of several families first prepares all their members in one call of the
    robot's ``prepare``; if that fails, each family prepares its own (and says why).
    """
    from wmr_mujoco.validation.members import run_family

    shared = 0.0
    if len(unit) > 1:
        spec = work[unit[0]][0]
        start = time.perf_counter()
        members = [m for i in unit for m in work[i][1].members(seed, draws)]
        try:
            spec.prepare(members, None)  # type: ignore[misc]
        except Exception:  # each family's own prepare then runs its members
            if progress:
                progress(f"{spec.name}: preparing {len(unit)} families together failed; "
                         f"each prepares its own:\n{traceback.format_exc()}")
        shared = (time.perf_counter() - start) / len(unit)
    out = []
    for i in unit:
        spec, s = work[i]
        start = time.perf_counter()
        result = run_family(spec, s, seed, draws, progress)
        result.seconds = time.perf_counter() - start + shared
        out.append((i, result))
    return out


def announce(result: ScenarioResult, done: int, total: int,
             progress: Callable[[str], None] | None,
             on_result: Callable[[ScenarioResult], None] | None) -> None:
    """Say that the ``done``-th of ``total`` families finished, and hand its result on."""
    if progress:
        progress(f"[{done}/{total}] {result.scenario.key}")
    if on_result:
        on_result(result)
