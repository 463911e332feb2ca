"""Is each robot's default step the cheapest that meets all its targets? (issue 24 § 4).

``python -m wmr_mujoco.bench.timestep_choice [--quick] [--seeds 0 1] [--jobs 2]
[--dampratios 0.5 0.8 1 | --keep-stiffness] [--write] [robots ...]`` answers, for every robot the
random-steps family drives (:func:`wmr_mujoco.bench.default_speed.drivable`), with the
robot's families rather than single runs:

1. **Cost**: the real-time factor of a bare one-thread ``mj_step`` loop in CPU time
   (member 0 of the random-steps family,
   :func:`~wmr_mujoco.bench.default_speed.real_time_factors`: every setting timed in
   alternating rounds of one run, median of the rounds; NaN: it diverged) at the default
   and at each longer step of :data:`STEPS`, and its cost ratio to the default.
2. **Fidelity**: every scenario family of ``wmr validate ROBOT --seed S`` at that step,
   compared row by row with the defaults' at the same seed
   (:func:`wmr_mujoco.bench.solver_fidelity.compare`): the targets the defaults meet and
   the longer step loses. A step is acceptable only if it loses none at any seed.

A longer step scales the contact's time constant with it (``t_c/Δt`` kept: every robot's
contact is set in steps of its timestep, the floor pairs' at
:data:`~wmr_mujoco.models.builders.wheel_pairs.WHEEL_PAIR_STEPS` by the builder, the
roller robots' ``contact_timeconst`` in their parameters), so a hand-over or an impact
is resolved over the same number of steps. The pairs' damping ratio ``ζ`` is the
robot's, or each of ``--dampratios``: ζ moves the rest depth, ``(1 − d) g ζ² t_c²``, and
with it the rolling radius, at the same damping. Only steps that divide every control
period users drive with (:data:`PERIODS`) are candidates: ``wmr_mujoco.drive`` refuses a
period that is not a whole number of steps.

``--keep-stiffness`` validates another family of candidates instead, in its own table:
each longer step with the default contact's spring kept
(:func:`~wmr_mujoco.bench.timestep_candidates.at_step_same_stiffness`: the robot's own
``t_c`` as far as the builder's least ``steps · Δt`` allows, and ζ lowered so that the
stiffness ``1/(d ζ² t_c²)``, the rest depth and the rolling radius stay the default's):
what a longer step costs when the contact is not made softer with it.

The default step is also validated at each other ζ (the same cost): its rows show why
the robot's ζ is chosen. Each candidate is validated on its own, families in registry
order, ``--jobs`` at a time; its validation stops after the first families that lose a
target (the table then names those; the later families are not run). The defaults'
figures, a candidate's complete figures and its stops are kept in
``reports/solver_cost/`` (named by the model files' digests,
:func:`~wmr_mujoco.bench.solver_fidelity.cache_file`; a stop also by the defaults' and
``--jobs``): a rerun times again and reuses them. ``--write`` pastes the table between
the ``timestep choice`` markers of ``docs/floor-contact.md`` (``timestep choice, stiffness
kept`` with ``--keep-stiffness``); with robots named, only their rows and verdict lines
(:func:`merged`), into a table whose header says it was made with the same options.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import time
from collections.abc import Sequence

import numpy as np

from wmr_mujoco.atomic import write_text_atomic
from wmr_mujoco.bench.default_speed import (
    FULL,
    QUICK,
    Rounds,
    chosen,
    drivable,
    real_time_factors,
)
from wmr_mujoco.bench.solver_fidelity import (
    CACHE,
    Figures,
    cache_file,
    compare,
    family_rows,
    figures,
    keep,
    kept,
)
from wmr_mujoco.bench.timestep_candidates import (  # noqa: F401 (re-exported)
    PERIODS,
    STEPS,
    Candidate,
    at_step,
    at_step_same_stiffness,
    candidates,
    pair_timeconst,
    stiffness_candidates,
)
from wmr_mujoco.docs_sync.markers import between, replace_between
from wmr_mujoco.lookup import validation_jobs
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.models.paths import DOCS_DIR
from wmr_mujoco.robots import get_spec
from wmr_mujoco.robots.spec import RobotSpec
from wmr_mujoco.validation.jobs import check_jobs
from wmr_mujoco.validation.pool import run_calls

DOC = DOCS_DIR / "floor-contact.md"
MARKER = "timestep choice"
STIFFNESS_MARKER = "timestep choice, stiffness kept"


@dataclasses.dataclass(frozen=True)
class Fidelity:
    """A candidate's validation at one seed against the defaults' at that seed.

    Attributes:
        lost: ``scenario / metric`` of the targets the defaults meet and it does not
            (:func:`~wmr_mujoco.bench.solver_fidelity.meets`), or whose rows it did not
            produce (a failed run).
        families: how many of the robot's families it ran (all, or up to the first loss).
        total: how many the robot has.
    """

    lost: tuple[str, ...]
    families: int
    total: int


def fidelity(spec: RobotSpec, params: RobotParams, seed: int, default: Figures,
             jobs: int) -> Fidelity:
    """Validate ``params`` family by family, ``jobs`` at a time, up to the first loss.

    Args:
        spec: the robot.
        params: the candidate's parameters.
        seed: the families' seed.
        default: the defaults' rows at ``seed``.
        jobs: families run at once (the stop comes after the first batch that loses).

    Returns:
        What the candidate loses, and how many families it ran. A complete pass is kept
        in :data:`CACHE` (its rows), as is a stop (named by the candidate, the defaults
        and ``jobs``); an unreadable kept stop is run again.
    """
    jobs_ = validation_jobs([spec.name])
    whole = kept(spec, params, seed, CACHE)
    if whole is not None:
        v = compare(default, whole)
        return Fidelity(v.lost + v.missing, len(jobs_), len(jobs_))
    # a stop is kept per candidate and defaults (both models' digests): new defaults
    # judge the candidate again
    base = spec.params_type() if spec.params_type is not None else params
    digest = cache_file(spec, base, seed, CACHE).stem.rsplit("-", 1)[-1]
    stopped = cache_file(spec, params, seed, CACHE).with_suffix(
        f".vs-{digest}.j{jobs}.stopped.json")
    if stopped.exists():  # an earlier run stopped at a loss against these defaults
        try:
            f = json.loads(stopped.read_text())
            return Fidelity(tuple(f["lost"]), int(f["families"]), int(f["total"]))
        except (ValueError, KeyError, TypeError):
            pass  # not a stop this module wrote: run again
    got: Figures = {}
    for start in range(0, len(jobs_), jobs):
        keys = range(start, min(len(jobs_), start + jobs))
        for rows in run_calls([(family_rows, (spec, k, seed, params)) for k in keys], jobs):
            got.update({(r.scenario, r.metric, r.unit): r for r in rows})  # type: ignore[attr-defined]
        names = {jobs_[k][1].name for k in range(keys.stop)}
        v = compare({k: r for k, r in default.items() if r.scenario in names}, got)
        if v.lost or v.missing:
            out = Fidelity(v.lost + v.missing, keys.stop, len(jobs_))
            stopped.parent.mkdir(parents=True, exist_ok=True)
            write_text_atomic(stopped, json.dumps(dataclasses.asdict(out)))
            return out
    keep(spec, params, seed, got, CACHE)
    return Fidelity((), len(jobs_), len(jobs_))


def study(spec: RobotSpec, seeds: Sequence[int], dampratios: Sequence[float], how: Rounds,
          jobs: int, stiffness_kept: bool = False) -> list[dict[str, object]]:
    """One row per setting of ``spec``: the default first, then :func:`candidates`.

    A candidate that loses a target at a seed is not validated at the later seeds (nor are
    the defaults, once no candidate is left).

    Args:
        spec: the robot.
        seeds: the families' seeds, in turn.
        dampratios: the floor pairs' ζ to try besides the robot's own.
        how: the timing.
        jobs: families run at once.
        stiffness_kept: the candidates are :func:`stiffness_candidates` instead
            (``dampratios`` unused).

    Returns:
        Dicts of ``robot``, ``timestep``, ``dampratio``, ``rtf``, ``ratio`` (cost against
        the default), ``verdict`` (a table cell) and, for a candidate, ``acceptable``.
    """
    assert spec.params_type is not None
    cands = stiffness_candidates(spec) if stiffness_kept else candidates(spec, dampratios)
    rtf = real_time_factors(spec, [None, *(c.params for c in cands)], how,
                            clock=time.process_time, diverged_nan=True)
    own = spec.params_type()
    out: list[dict[str, object]] = [{"robot": spec.name, "timestep": own.sim.timestep,
                                     "dampratio": own.sim.floor_dampratio, "rtf": rtf[0],
                                     "ratio": 1.0, "verdict": "the default"}]
    verdicts: list[dict[int, Fidelity]] = [{} for _ in cands]
    for seed in seeds:
        alive = [np.isfinite(r) and all(not f.lost for f in v.values())
                 for v, r in zip(verdicts, rtf[1:], strict=True)]
        if not any(alive):
            break
        base = figures(spec, own, seed, jobs, CACHE)
        for c, v, go in zip(cands, verdicts, alive, strict=True):
            if go:
                v[seed] = fidelity(spec, c.params, seed, base, jobs)
                print(f"  {spec.name} {1e3 * c.timestep:g} ms ζ {c.dampratio:g} seed {seed}: "
                      f"{verdict_text(v)}", flush=True)
    for c, r, v in zip(cands, rtf[1:], verdicts, strict=True):
        out.append({"robot": spec.name, "timestep": c.timestep, "dampratio": c.dampratio,
                    "stiffness_kept": c.stiffness_kept, "rtf": r, "ratio": rtf[0] / r,
                    "verdict": verdict_text(v) if v else "diverged on the timing drive",
                    "acceptable": bool(v) and all(not f.lost for f in v.values())})
    return out


def verdict_text(by_seed: dict[int, Fidelity]) -> str:
    """One table cell: per seed, passes every target or which it loses."""
    parts = []
    for seed, f in by_seed.items():
        if not f.lost:
            parts.append(f"seed {seed}: keeps every target")
            continue
        shown = "; ".join(f.lost[:3]) + (f"; … {len(f.lost) - 3} more" if len(f.lost) > 3 else "")
        ran = ("" if f.families == f.total
               else f" (stopped after {f.families} of {f.total} families)")
        parts.append(f"seed {seed}: loses {len(f.lost)}{ran}: {shown}")
    return "; ".join(parts)


def table(rows: list[dict[str, object]], seeds: Sequence[int], how: Rounds,
          quick: bool, stiffness_kept: bool = False) -> str:
    """The markdown table of :func:`study`'s rows, and a verdict line per robot.

    Args:
        rows: :func:`study`'s rows.
        seeds: the seeds validated (for the header).
        how: the timing (for the header).
        quick: the run was ``--quick`` (the header says so).
        stiffness_kept: the rows are :func:`stiffness_candidates` (the header says so).
    """
    contact = ("the contact's stiffness kept (`--keep-stiffness`: its own t_c, raised by the "
               "builder to its least steps · Δt, t_c', and ζ' = ζ t_c/t_c')"
               if stiffness_kept else "contact time constant scaled with the step")
    lines = [f"{'QUICK run: ' if quick else ''}`python -m wmr_mujoco.bench.timestep_choice`: "
             f"each robot's families (`wmr validate ROBOT --seed S`, seeds "
             f"{', '.join(map(str, seeds))}) at each longer step that divides the 20, 50 and "
             f"100 ms control periods, {contact}; cost: "
             f"one-thread `mj_step` loop in CPU time, {how.seconds:g} s of the random-steps "
             f"family's member 0, median of {how.rounds} alternating rounds.", "",
             "| robot | step | ζ | real-time × | cost ratio (candidate / default) | "
             "targets the defaults meet (judged and passed, or open and met) |",
             "|---" * 6 + "|"]
    for r in rows:
        lines.append(f"| {r['robot']} | {1e3 * float(r['timestep']):g} ms "  # type: ignore[arg-type]
                     f"| {float(r['dampratio']):.3g} | {_cell(r['rtf'], '.0f', '×')} "
                     f"| {_cell(r['ratio'], '.2f')} | {r['verdict']} |")
    lines.append("")
    for name in dict.fromkeys(str(r["robot"]) for r in rows):
        own = float(next(r["timestep"] for r in rows if r["robot"] == name))  # type: ignore[arg-type]
        longer = [r for r in rows if r["robot"] == name and r.get("acceptable")
                  and float(r["timestep"]) > own]  # type: ignore[arg-type]
        lines.append(f"- {name}: " + (
            "no longer step keeps every target the defaults meet: the default step is the "
            "cheapest." if not longer
            else "a longer step keeps every target the defaults meet: " + ", ".join(
                f"{1e3 * float(r['timestep']):g} ms at ζ = {float(r['dampratio']):.3g} "  # type: ignore[arg-type]
                f"(cost ratio {float(r['ratio']):.2f})"  # type: ignore[arg-type]
                for r in longer) + "."))
    return "\n".join(lines)


def merged(old: str, new: str, robots: Sequence[str]) -> str:
    """``old`` table with the rows and verdict lines of ``robots`` taken from ``new``.

    The header is ``new``'s; rows and verdict lines come in registry order
    (:func:`~wmr_mujoco.bench.default_speed.drivable`), each robot's from ``new`` if it is
    one of ``robots``, else from ``old``. A robot ``old`` does not hold and ``new`` does
    not give is left out.
    """
    def parts(text: str) -> tuple[list[str], dict[str, list[str]], dict[str, list[str]]]:
        head: list[str] = []
        rows: dict[str, list[str]] = {}
        verdicts: dict[str, list[str]] = {}
        for line in text.strip().splitlines():
            name = line.split("|")[1].strip() if line.startswith("| ") else ""
            if name and name != "robot":
                rows.setdefault(name, []).append(line)
            elif line.startswith("- ") and ":" in line:
                verdicts.setdefault(line[2:].split(":", 1)[0], []).append(line)
            elif not rows:
                head.append(line)
        return head, rows, verdicts

    _, old_rows, old_verdicts = parts(old)
    head, new_rows, new_verdicts = parts(new)
    order = [r for r in drivable() if r in old_rows or r in new_rows]
    pick = {r: (new_rows, new_verdicts) if r in robots else (old_rows, old_verdicts)
            for r in order}
    body = [line for r in order for line in pick[r][0].get(r, [])]
    tail = [line for r in order for line in pick[r][1].get(r, [])]
    return "\n".join([*head, *body, "", *tail])


def _cell(value: object, fmt: str, unit: str = "") -> str:
    """A figure of the table, or ``diverged`` for a NaN (the timing drive diverged)."""
    x = float(value)  # type: ignore[arg-type]
    return f"{x:{fmt}}{unit}" if np.isfinite(x) else "diverged"


def main(argv: list[str] | None = None) -> None:
    """Command line: print (and with ``--write`` publish) the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="shorter timing, seed 0 only")
    parser.add_argument("--seeds", type=int, nargs="+", default=None,
                        help="validation seeds (default 0 1; --quick: 0)")
    parser.add_argument("--dampratios", type=float, nargs="+", default=(),
                        help="floor pairs' ζ to try at each step (default: each robot's own)")
    parser.add_argument("--keep-stiffness", action="store_true",
                        help="candidates: each longer step with the contact's stiffness kept "
                             f"(its own table, {STIFFNESS_MARKER!r} markers)")
    parser.add_argument("--jobs", type=int, default=2, help="worker processes (default 2)")
    parser.add_argument("--write", action="store_true",
                        help=f"paste the table into {DOC.name} ({MARKER!r} markers, "
                             f"{STIFFNESS_MARKER!r} with --keep-stiffness); robots named: "
                             "only their rows, into a table made with the same options")
    parser.add_argument("robots", nargs="*", help="robots (default: every drivable robot)")
    args = parser.parse_args(argv)
    check_jobs(args.jobs)
    if args.keep_stiffness and args.dampratios:
        parser.error("--keep-stiffness sets each candidate's ζ; leave --dampratios out")
    for z in args.dampratios:
        if not 0.1 <= z <= 1.0:
            parser.error(f"--dampratios {z!r}: each must be in [0.1, 1]")
    seeds = args.seeds or ([0] if args.quick else [0, 1])
    if any(s < 0 for s in seeds):
        parser.error(f"--seeds {seeds!r}: seeds are integers >= 0")
    robots = chosen(parser, args.robots)
    how = QUICK if args.quick else FULL
    marker = STIFFNESS_MARKER if args.keep_stiffness else MARKER
    old = between(DOC, marker) if args.write and args.robots else None
    header = table([], seeds, how, args.quick, stiffness_kept=args.keep_stiffness)
    if old is not None and old.splitlines()[:1] != header.splitlines()[:1]:
        parser.error(f"the table in {DOC.name} was made with other options (its header: "
                     f"{old.splitlines()[:1]}); rerun it with those, or for every robot")
    rows = []
    for name in robots:
        rows += study(get_spec(name), seeds, args.dampratios, how, args.jobs,
                      stiffness_kept=args.keep_stiffness)
    text = table(rows, seeds, how, args.quick, stiffness_kept=args.keep_stiffness)
    print(text)
    if args.write:
        if old is not None:  # the other robots' rows stay as the table has them
            text = merged(old, text, robots)
        replace_between(DOC, marker, text)
        print(f"wrote {DOC}")


if __name__ == "__main__":
    main()
