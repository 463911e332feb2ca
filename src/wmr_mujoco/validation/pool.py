"""Scenario families over a process pool: ``wmr validate --jobs N``.

The families of a validation are independent: each loads its own model, draws its own
members from ``(seed, scenario key)`` and runs them (:func:`~wmr_mujoco.validation.members.
run_family`). :func:`run_pooled` hands them to ``N`` worker processes, each running whole
units one after the other (a family, or a robot's families prepared together:
:mod:`wmr_mujoco.validation.units`), and puts the results back in the declared order, so that
everything printed and written after the run is what one process gives (the same
figures, bit for bit: a family's result does not depend on which process ran it or what
ran before it there). What comes back in completion order is only the progress line
``"[k/n] robot/scenario"`` (numbered by completion, as in one process) and ``on_result``.

The workers are forked from the command's process, so that they share its registry
entries (scenarios carry their robots' code, which need not pickle); a result comes back
without its scenarios (:class:`Detached`), which the parent puts back from its own, and
with its members' rows, draws and errors but not their traces (the family's own trace,
its worst member's, comes back; with ``draw``, its figure too, drawn in the worker). Where
``fork`` is not available (Windows), or for one job, the families run in this process.

Interrupts: the workers ignore Ctrl-C and die of SIGTERM; the command's process gets
both, and on its way out terminates the pool (:func:`run_pooled`'s ``finally``). Workers
write nothing (a figure comes back as a PNG file's bytes), so an interrupted run leaves
nothing behind (the report is written by the command's process, atomically, after every
family is done).

Order of hand-out: the longest families first where an earlier run's per-family times
are known (``hints``, from the report already in the output folder), families without
a time before them in declared order; this only shortens the run's tail.
"""

from __future__ import annotations

import json
import multiprocessing
import signal
import traceback
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from wmr_mujoco.validation.jobs import check_jobs
from wmr_mujoco.validation.metrics import Trace
from wmr_mujoco.validation.runner import Job, ScenarioResult
from wmr_mujoco.validation.scenarios import Scenario
from wmr_mujoco.validation.targets import Row
from wmr_mujoco.validation.units import announce, run_unit, unit_hint, units


def can_fork() -> bool:
    """Whether worker processes can be forked here."""
    return "fork" in multiprocessing.get_all_start_methods()


@dataclass(frozen=True)
class Detached:
    """A :class:`ScenarioResult` without its scenarios (what pickles across processes).

    ``draw``: the member's draw (None: the result of the scenario itself). A member
    comes without its trace: the family's own trace is its worst member's
    (:func:`~wmr_mujoco.validation.members.family_result`), the one the report plots, and
    nothing after a run reads any other member's (sending them all, every recorded
    sample a small array to pickle and read back, took CPU time from the families).
    ``figure``: the result's figure as drawn in the worker (``ScenarioResult.figure``).
    """

    draw: Mapping[str, float] | None
    rows: list[Row]
    trace: Trace
    error: str | None
    members: tuple[Detached, ...]
    seed: int | None
    seconds: float | None
    figure: bytes | None = None


def detach(result: ScenarioResult, member: bool = False) -> Detached:
    """``result`` without its scenario objects (``member``: its draw, without its trace)."""
    return Detached(dict(result.scenario.draw) if member else None, result.rows,
                    Trace() if member else result.trace, result.error,
                    tuple(detach(m, True) for m in result.members), result.seed,
                    result.seconds, result.figure)


def attach(detached: Detached, scenario: Scenario) -> ScenarioResult:
    """The result of ``scenario`` (its members from ``scenario.member(draw)``)."""
    members = [attach(m, scenario.member(m.draw or {})) for m in detached.members]
    return ScenarioResult(scenario, detached.rows, detached.trace, detached.error, members,
                          detached.seed, detached.seconds, detached.figure)


def time_hints(folder: Path) -> dict[str, float]:
    """Per scenario key, its family's seconds in the report in ``folder`` (empty: none)."""
    try:
        records = json.loads((Path(folder) / "validation.json").read_text())["scenarios"]
        return {f"{r['robot']}/{r['scenario']}": float(r["seconds"]) for r in records
                if isinstance(r, dict) and isinstance(r.get("seconds"), (int, float))}
    except (OSError, ValueError, KeyError, TypeError):
        return {}


def hand_out_order(work: Sequence[Job], hints: Mapping[str, float] | None) -> list[int]:
    """Indices of the units of ``work``: those without a hint first, then longest first.

    Units: :func:`~wmr_mujoco.validation.units.units` (in declared order); a unit's hint
    is the sum of its families'.
    """
    hints = hints or {}
    groups = units(work)
    times = [unit_hint(work, u, hints) for u in groups]
    unknown = [j for j, t in enumerate(times) if t is None]
    known = sorted((j for j, t in enumerate(times) if t is not None),
                   key=lambda j: (-times[j], j))  # type: ignore[operator]
    return unknown + known


#: Draws a result's figure (PNG bytes, None: nothing to draw): ``run_families``'s ``draw``.
Draw = Callable[[ScenarioResult], "bytes | None"]

#: What the forked workers run: the jobs, the seed, the draw count and the figure drawer
#: (set before forking).
_SHARED: dict[str, object] = {}


def _init_worker() -> None:
    """Workers leave Ctrl-C to the command's process and die of SIGTERM."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def _run_one(j: int) -> tuple[list[tuple[int, Detached]], list[str]]:
    """Unit ``j`` of the shared jobs, each family timed (and drawn); the notes kept."""
    notes: list[str] = []
    done = run_unit(_SHARED["work"], _SHARED["units"][j], _SHARED["seed"],  # type: ignore
                    _SHARED["draws"], notes.append)  # type: ignore[arg-type]
    draw = _SHARED["draw"]
    if draw is not None:
        for _, result in done:
            with_figure(result, draw, notes.append)  # type: ignore[arg-type]
    return [(i, detach(result)) for i, result in done], notes


def with_figure(result: ScenarioResult, draw: Draw,
                progress: Callable[[str], None] | None = None) -> ScenarioResult:
    """``result`` with its ``figure`` drawn; a figure that fails to draw is left to the report.

    The figure is drawn after the family's ``seconds`` were taken, so they stay its own.
    """
    try:
        result.figure = draw(result)
    except Exception:  # the report draws it again, and raises there
        if progress:
            progress(f"{result.scenario.key}: drawing its figure failed; the report "
                     f"draws it:\n{traceback.format_exc()}")
    return result


def _call(i: int) -> object:
    """Call ``i`` of the shared calls."""
    fn, args = _SHARED["calls"][i]  # type: ignore[index]
    return fn(*args)


def run_calls(calls: Sequence[tuple[Callable[..., object], tuple[object, ...]]],
              jobs: int = 1) -> list[object]:
    """``[fn(*args) for fn, args in calls]``, in ``jobs`` forked processes if > 1.

    For independent work whose results pickle (the report's plots, each written by its
    call): the same results in the same order as in this process.
    """
    check_jobs(jobs)
    if jobs == 1 or len(calls) < 2 or not can_fork():
        return [fn(*args) for fn, args in calls]
    _SHARED.update(calls=list(calls))
    pool = multiprocessing.get_context("fork").Pool(min(jobs, len(calls)), _init_worker)
    try:
        out = pool.map(_call, range(len(calls)), chunksize=1)
        pool.close()
    finally:
        pool.terminate()
        pool.join()
        _SHARED.clear()
    return out


def run_pooled(work: Sequence[Job], jobs: int, seed: int, draws: int | None,
               progress: Callable[[str], None] | None = None,
               on_result: Callable[[ScenarioResult], None] | None = None,
               hints: Mapping[str, float] | None = None,
               draw: Draw | None = None) -> list[ScenarioResult]:
    """Every family of ``work`` in ``jobs`` forked processes; results in declared order.

    ``progress`` gets each family's notes and then ``"[k/n] robot/scenario"`` as the
    k-th result is back; ``on_result`` sees each result as it is back. ``seed``,
    ``draws`` and ``draw`` as :func:`~wmr_mujoco.validation.members.run_families`
    (checked there); the workers draw the figures, each after its unit.

    Raises:
        ValueError: a bad ``jobs``; or ``fork`` is not available here.
    """
    check_jobs(jobs)
    if not can_fork():
        raise ValueError("worker processes need the 'fork' start method, which this "
                         "platform lacks; use jobs=1")
    results: list[ScenarioResult | None] = [None] * len(work)
    groups = units(work)
    _SHARED.update(work=list(work), units=groups, seed=seed, draws=draws, draw=draw)
    pool = multiprocessing.get_context("fork").Pool(min(jobs, len(groups)), _init_worker)
    try:
        order = hand_out_order(work, hints)
        done = 0
        for batch, notes in pool.imap_unordered(_run_one, order, chunksize=1):
            if progress:
                for note in notes:
                    progress(note)
            for i, detached in batch:
                result = attach(detached, work[i][1])
                results[i] = result
                done += 1
                announce(result, done, len(work), progress, on_result)
        pool.close()
    finally:
        pool.terminate()
        pool.join()
        _SHARED.clear()
    assert all(r is not None for r in results)
    return results  # type: ignore[return-value]
