"""A scenario's family, run member by member and judged by its worst.

A scenario with a family (:mod:`wmr_mujoco.validation.family`) runs as its seeded members
(:func:`run_family`): each member is the scenario with its draw, run like a single
scenario by :mod:`wmr_mujoco.validation.runner` (the generic variations of
:mod:`wmr_mujoco.validation.variations` applied). The members of a kinematic or dynamic
family are prepared on one compiled model and simulated together in threaded
``mujoco.rollout`` calls (:data:`NTHREAD` threads, at most :data:`BATCH_BYTES` of
recorded states per call), then measured one by one; a measurement scenario's members
each go through its ``evaluate``. The family's rows are its worst member's per metric
(:mod:`wmr_mujoco.validation.worst`): a failing member fails the scenario. Every
member's own result is kept (``ScenarioResult.members``) for the report's spread
(after a run in worker processes, without its trace: :mod:`~wmr_mujoco.validation.pool`).
"""

from __future__ import annotations

import traceback
from collections.abc import Callable, Mapping, Sequence

import mujoco
import numpy as np

from wmr_mujoco.models.loading import load
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.sim.engine import STATE_SPEC, simulate_starts
from wmr_mujoco.validation.family import DEFAULT_SEED, check_draws, check_seed, describe
from wmr_mujoco.validation.metrics import Trace
from wmr_mujoco.validation.pool import Draw, can_fork, check_jobs, run_pooled, with_figure
from wmr_mujoco.validation.runner import (
    Job,
    Prepared,
    ScenarioResult,
    guarded,
    measure,
    prepare,
    run_scenario,
)
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.spec import RobotSpec
from wmr_mujoco.validation.units import announce, run_unit, units
from wmr_mujoco.validation.worst import worst_member, worst_rows

#: Threads of a family's batched rollout (the machines this runs on have two cores).
NTHREAD = 2
#: Most bytes of recorded states one batched rollout of a family's members may hold.
BATCH_BYTES = 64 * 2**20


def run_family(spec: RobotSpec, s: Scenario, seed: int = DEFAULT_SEED,
               draws: int | None = None, progress: Callable[[str], None] | None = None,
               params: RobotParams | None = None) -> ScenarioResult:
    """Run every member of ``s``'s family and judge the worst.

    ``draws`` of them (default: the family's); a failing member never raises, its error
    fails the family.

    A scenario without a family is one run (:func:`run_scenario`).

    Raises:
        ValueError: a bad ``seed`` or ``draws`` (before anything runs).
    """
    members = s.members(seed, draws)
    if s.family is None:
        return run_scenario(spec, s, progress, params=params)
    if s.kind is ScenarioKind.MEASUREMENT:
        if spec.prepare is not None:
            try:  # the robot runs its members batched; each evaluate then finds its run
                spec.prepare(members, params)
            except Exception:  # an unprepared member still runs on its own
                if progress:
                    progress(traceback.format_exc())
        results = [run_scenario(spec, m, progress, params=params) for m in members]
    else:
        results = run_batched(spec, members, progress, params)
    return family_result(s, results, seed)


def family_result(s: Scenario, results: list[ScenarioResult], seed: int | None
                  ) -> ScenarioResult:
    """The family's result from its members' (worst rows, the worst member's trace)."""
    rows = [r.rows for r in results]
    worst = results[worst_member(rows)]
    errors = [f"{describe(r.scenario.draw)}: {r.error}" for r in results if r.error]
    return ScenarioResult(s, worst_rows(rows, [r.scenario.draw for r in results]),
                          worst.trace, errors[0] if errors else None, list(results), seed)


def run_batched(spec: RobotSpec, members: list[Scenario],
                progress: Callable[[str], None] | None, params: RobotParams | None
                ) -> list[ScenarioResult]:
    """Kinematic or dynamic members: prepared on one model, simulated in batches.

    A member that fails to prepare, or a batch that diverges, is rerun alone through
    :func:`run_scenario` (which says which member and why).
    """
    out: dict[int, ScenarioResult] = {}
    preps: dict[int, Prepared] = {}
    try:
        model = load(spec, params)
    except Exception:  # each member's own run says why
        return [run_scenario(spec, m, progress, params=params) for m in members]
    for i, m in enumerate(members):
        try:
            preps[i] = prepare(spec, m, params, model=model)
        except Exception:
            out[i] = run_scenario(spec, m, progress, params=params)
    if preps:
        nstate = mujoco.mj_stateSize(model, STATE_SPEC)
        nstep = max(len(p.controls) for p in preps.values()) + 1
        chunk = max(1, BATCH_BYTES // (8 * nstate * nstep))
        order = sorted(preps)
        for c in range(0, len(order), chunk):
            group = order[c:c + chunk]
            try:
                batch = simulate_starts(model, [preps[i].data for i in group],
                                        [preps[i].controls for i in group], NTHREAD)
            except Exception:  # an unprepared member still runs on its own
                out.update({i: run_scenario(spec, members[i], progress, params=params)
                            for i in group})
                continue
            for i, states in zip(group, batch, strict=True):
                def measured(prep: Prepared = preps[i], st: np.ndarray = states
                             ) -> ScenarioResult:
                    trace = Trace()
                    return ScenarioResult(prep.scenario, measure(prep, st, trace), trace)

                out[i] = guarded(members[i], measured, progress)
    return [out[i] for i in range(len(members))]


def run_families(work: Sequence[Job], progress: Callable[[str], None] | None = None,
                 on_result: Callable[[ScenarioResult], None] | None = None,
                 seed: int = DEFAULT_SEED, draws: int | None = None, jobs: int = 1,
                 hints: Mapping[str, float] | None = None,
                 draw: Draw | None = None) -> list[ScenarioResult]:
    """Run every scenario's family; a failure does not stop the others.

    ``seed`` draws the members (:meth:`Family.sample`), ``draws`` overrides every
    family's number of draws (None: the declared ones). ``jobs`` > 1 runs the families
    in that many worker processes (:func:`wmr_mujoco.validation.pool.run_pooled`; one
    process where forking is not available), with the same results in the same order;
    ``hints`` (scenario key -> seconds of an earlier run) hands the longest out first.
    ``progress`` gets one line ``"[k/n] robot/scenario"`` as the k-th result is there
    (numbered by completion), besides the tracebacks of failed runs; ``on_result`` sees
    each result as soon as it is there. Each result's ``seconds`` is its family's wall
    time. A robot's families prepared together run as one unit
    (:mod:`wmr_mujoco.validation.units`). ``draw`` (e.g. the report's
    :func:`~wmr_mujoco.validation.plots.scenario_png`) draws each result's ``figure``
    where the result was made, after its family was timed: the worker processes draw
    beside the families instead of after all of them.

    Raises:
        ValueError: a bad ``seed``, ``draws`` or ``jobs``, before anything runs.
    """
    check_seed(seed)  # a bad seed or draw count fails before any work
    if draws is not None:
        check_draws(draws)
    check_jobs(jobs)
    if jobs > 1 and len(work) > 1 and can_fork():
        return run_pooled(work, jobs, seed, draws, progress, on_result, hints, draw)
    results: list[ScenarioResult | None] = [None] * len(work)
    done = 0
    for unit in units(work):  # a robot's families prepared together run together
        for i, result in run_unit(work, unit, seed, draws, progress):
            results[i] = result if draw is None else with_figure(result, draw, progress)
            done += 1
            announce(result, done, len(work), progress, on_result)
    return results  # type: ignore[return-value]
