"""omni3's measurement families: N, median, worst and target of every judged figure.

``python -m wmr_mujoco.bench.omni_families [--seed S ...] [--before] [--draws N]``

Every omni3 measurement scenario's family (:mod:`wmr_mujoco.robots.omni3.families`) is
drawn with each seed, all members run in one batch per kind
(:func:`~wmr_mujoco.robots.omni3.families.prepare`) and evaluated one by one; per judged
figure the table prints the number of draws, the median, the worst draw's value and
the draw itself, the target and how many draws meet it. ``--before`` runs the models as
they were before issue 24 (the hand-over overlap timed by the wheel's rate alone, the
slip onset predicted quasi-statically at rest), on the same draws and physics.
"""

from __future__ import annotations

import argparse
import math
import time
from collections.abc import Sequence

import numpy as np

from wmr_mujoco.robots.omni3 import SPEC, families, members, traction
from wmr_mujoco.validation.family import DEFAULT_SEED, describe
from wmr_mujoco.validation.scenarios import MeasurementResult, Scenario, ScenarioKind

#: Most draws per family from the command line.
MAX_DRAWS = 100


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
    """Prepare all members in one batch, then evaluate each."""
    if before:
        from wmr_mujoco.robots.omni3 import DYNAMIC_SPECS

        base = {s.name: s for s in DYNAMIC_SPECS}
        members.prepare([members.member_spec(s, base[s.name]) for s in scenarios
                         if s.name in base], None, turning=False)
    families.prepare(scenarios, None)
    out = []
    for sc in scenarios:
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


def main(argv: Sequence[str] | None = None) -> int:
    """Print the families' table for each seed; exit 1 if a worst draw misses its target."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, nargs="+", default=[DEFAULT_SEED])
    ap.add_argument("--draws", type=int, default=None,
                    help=f"draws per family (default: the family's; at most {MAX_DRAWS})")
    ap.add_argument("--before", action="store_true",
                    help="the models before issue 24, on the same draws")
    args = ap.parse_args(argv)
    if any(s < 0 for s in args.seed):
        ap.error(f"--seed {args.seed}: seeds are integers >= 0")
    if args.draws is not None and not 1 <= args.draws <= MAX_DRAWS:
        ap.error(f"--draws {args.draws}: valid range is 1..{MAX_DRAWS}")
    missed = False
    for seed in args.seed:
        t0 = time.perf_counter()
        results = evaluate_members(family_members(seed, args.draws), args.before)
        wall = time.perf_counter() - t0
        print(f"\nomni3 measurement families, seed {seed}"
              f"{' (models before issue 24)' if args.before else ''}: "
              f"{len(results)} members in {wall:.1f} s")
        print(f"{'scenario':26s} {'figure':52s} {'N':>3s} {'median':>8s} {'worst':>8s} "
              f"{'target':>7s} {'met':>5s}  worst draw")
        for r in table(results):
            missed |= r["worst"] > r["target"]  # type: ignore[operator]
            print(f"{r['scenario']:26.26s} {r['figure']:52.52s} {r['n']:3d} "
                  f"{r['median']:8.3g} {r['worst']:8.3g} {r['target']:7.3g} "
                  f"{r['met']:2d}/{r['n']:<2d}  {r['worst draw']}")
    traction._READY.clear()
    return 1 if missed else 0


if __name__ == "__main__":
    raise SystemExit(main())
