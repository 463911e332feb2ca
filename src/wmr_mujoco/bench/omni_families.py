"""omni3's measurement families: N, median, worst and target of every judged figure.

``python -m wmr_mujoco.bench.omni_families [--seed S ...] [--before] [--draws N] [--write]``

Every omni3 measurement scenario's family (:mod:`wmr_mujoco.robots.omni3.families`) is
drawn with each seed, all members run in one batch per kind
(:func:`~wmr_mujoco.robots.omni3.families.prepare`) and evaluated one by one; per judged
figure the table prints the number of draws, the median, the worst draw's value and
the draw itself, the target and how many draws meet it. ``--before`` runs the models as
they were before issue 24 (the hand-over overlap timed by the wheel's rate alone, the
slip onset predicted quasi-statically at rest), on the same draws and physics.
``--write`` pastes the tables of both model versions into ``docs/omni-dynamics.md``
(§ 13; it runs each seed twice).
"""

from __future__ import annotations

import argparse
import math
import time
from collections.abc import Sequence

import numpy as np

from wmr_mujoco.docs_sync.markers import publish
from wmr_mujoco.models.paths import REPO_ROOT
from wmr_mujoco.robots.omni3 import SPEC, families, members, traction
from wmr_mujoco.validation.family import DEFAULT_SEED, describe
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario, ScenarioKind

#: Most draws per family from the command line.
MAX_DRAWS = 100
#: Most members prepared at once (below ``members.MAX_READY``).
BATCH = 320


def family_members(seed: int, draws: int | None = None) -> list[Scenario]:
    """Every member of every omni3 measurement family for ``seed``."""
    out = []
    for sc in SPEC.scenarios:
        if sc.kind is ScenarioKind.MEASUREMENT and sc.family is not None:
            out += [sc.member(d) for d in sc.family.sample(seed, sc.key, draws)]
    return out


def _before(result: MeasurementResult) -> MeasurementResult:
    """The slip onset judged against the quasi-static prediction (the model before)."""
    values = {m.name: m for m in result.metrics}
    if "slip-onset torque, quasi-static at rest" not in values:
        return result
    measured = values["slip-onset torque, physics"].value
    predicted = values["slip-onset torque, quasi-static at rest"].value
    judged = values["slip-onset torque: predicted vs physics"]
    row = judged._replace(value=100 * abs(predicted - measured) / measured,
                          note="quasi-static prediction at rest")
    return MeasurementResult([row if m is judged else m for m in result.metrics],
                             result.series)


def evaluate_members(scenarios: Sequence[Scenario], before: bool = False
                     ) -> list[tuple[Scenario, MeasurementResult]]:
    """Members run in batches of whole scenarios, then evaluated one by one.

    A batch holds at most :data:`BATCH` members (a scenario's draws stay together).
    """
    from wmr_mujoco.robots.omni3 import DYNAMIC_SPECS

    base = {s.name: s for s in DYNAMIC_SPECS}
    batches: list[list[Scenario]] = [[]]
    for name in dict.fromkeys(s.name for s in scenarios):
        group = [s for s in scenarios if s.name == name]
        if batches[-1] and len(batches[-1]) + len(group) > BATCH:
            batches.append([])
        batches[-1] += group
    out = []
    for batch in batches:
        if before:
            members.prepare([members.member_spec(s, base[s.name]) for s in batch
                             if s.name in base], None, turning=False)
        families.prepare(batch, None)
        for sc in batch:
            res = sc.evaluate(sc, None)
            out.append((sc, _before(res) if before else res))
    return out


def table(results: list[tuple[Scenario, MeasurementResult]]) -> list[dict[str, object]]:
    """One row per (scenario, judged figure): N, median, worst (and its draw), target."""
    rows: dict[tuple[str, str], list[tuple[float, Scenario, float]]] = {}
    for sc, res in results:
        for m in res.metrics:
            if m.target is not None:
                rows.setdefault((sc.name, m.name), []).append((m.value, sc, m.target.value))
    out = []
    for (name, metric), vals in rows.items():
        v = np.array([abs(x[0]) if math.isfinite(x[0]) else math.inf for x in vals])
        worst = int(np.argmax(v))
        out.append({"scenario": name, "figure": metric, "n": len(v),
                    "median": float(np.median(v)), "worst": float(v[worst]),
                    "target": vals[0][2], "met": int(np.sum(v <= vals[0][2])),
                    "worst draw": describe(vals[worst][1].draw)})
    return out


#: The page and marker key of the tables.
DOC = REPO_ROOT / "docs" / "omni-dynamics.md"
KEY = "omni dynamics: families"


def markdown(tables: Sequence[tuple[int, bool, float, list[dict[str, object]]]]) -> str:
    """The tables as Markdown, one per (seed, before) with its members' wall time."""
    out = []
    for seed, before, wall, rows in tables:
        out.append(f"**seed {seed}, {'before' if before else 'after'} issue 24** "
                   f"({rows[0]['n'] if rows else 0} draws per family; "
                   f"all members in {wall:.0f} s)\n")
        out.append("| scenario | figure | median | worst | target | met | worst draw |")
        out.append("|---|---|---|---|---|---|---|")
        out += [f"| {r['scenario']} | {r['figure']} | {r['median']:.3g} | {r['worst']:.3g} "
                f"| {r['target']:.3g} | {r['met']}/{r['n']} | {r['worst draw']} |"
                for r in rows]
        out.append("")
    return "\n".join(out)


def main(argv: Sequence[str] | None = None) -> int:
    """Print the families' table for each seed; exit 1 if a worst draw misses its target."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, nargs="+", default=[DEFAULT_SEED])
    ap.add_argument("--draws", type=int, default=None,
                    help=f"draws per family (default: the family's; at most {MAX_DRAWS})")
    ap.add_argument("--before", action="store_true",
                    help="the models before issue 24, on the same draws")
    ap.add_argument("--write", action="store_true",
                    help=f"both model versions, pasted into {DOC.name}")
    args = ap.parse_args(argv)
    if any(s < 0 for s in args.seed):
        ap.error(f"--seed {args.seed}: seeds are integers >= 0")
    if args.draws is not None and not 1 <= args.draws <= MAX_DRAWS:
        ap.error(f"--draws {args.draws}: valid range is 1..{MAX_DRAWS}")
    missed = False
    done = []
    for seed, before in [(s, b) for s in args.seed
                         for b in ((False, True) if args.write else (args.before,))]:
        t0 = time.perf_counter()
        results = evaluate_members(family_members(seed, args.draws), before)
        wall = time.perf_counter() - t0
        done.append((seed, before, wall, table(results)))
        print(f"\nomni3 measurement families, seed {seed}"
              f"{' (models before issue 24)' if before else ''}: "
              f"{len(results)} members in {wall:.1f} s")
        print(f"{'scenario':26s} {'figure':52s} {'N':>3s} {'median':>8s} {'worst':>8s} "
              f"{'target':>7s} {'met':>5s}  worst draw")
        for r in done[-1][3]:
            missed |= r["worst"] > r["target"]  # type: ignore[operator]
            print(f"{r['scenario']:26.26s} {r['figure']:52.52s} {r['n']:3d} "
                  f"{r['median']:8.3g} {r['worst']:8.3g} {r['target']:7.3g} "
                  f"{r['met']:2d}/{r['n']:<2d}  {r['worst draw']}")
    traction._READY.clear()
    if args.write:
        publish(DOC, {KEY: markdown(done)}, True)
    return 1 if missed else 0


if __name__ == "__main__":
    raise SystemExit(main())
