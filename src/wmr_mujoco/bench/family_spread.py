"""Is a family's spread small enough for fewer draws? ``python -m wmr_mujoco.bench.family_spread``.

A kinematic family may judge fewer draws than the 20 of a dynamic one
(:data:`~wmr_mujoco.validation.variations.KINEMATIC_DRAWS`) only where its spread is shown
small. This runs each such family (of the robots named, default every robot; or the
scenarios named) with :data:`~wmr_mujoco.validation.variations.DYNAMIC_DRAWS` draws at the
seed and prints, per judged metric: the declared draws N, the worst of the first N draws
(what ``wmr validate`` judges: the first N of the same seeded stream) and the worst of all
20, each over its target, and whether the spread is small: the worst of 20 at most
:data:`SMALL` of the target, so that the N draws judge a family whose worst over 20 still
keeps a twofold margin. Prints only; nothing is written.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Sequence

from wmr_mujoco.robots import ROBOTS, get_spec
from wmr_mujoco.validation.family import DEFAULT_SEED
from wmr_mujoco.validation.family_report import judged_spreads
from wmr_mujoco.validation.members import family_result, run_family
from wmr_mujoco.validation.variations import DYNAMIC_DRAWS
from wmr_mujoco.validation.worst import badness

#: Largest worst-of-20 over the target that counts as a small spread.
SMALL = 0.5


def rows(robot: str, scenario: str | None, seed: int, draws: int) -> list[tuple[str, ...]]:
    """One row per judged metric of each family that declares fewer than ``draws`` draws."""
    spec = get_spec(robot)
    chosen = [spec.scenario(scenario)] if scenario else spec.scenarios
    out = []
    for s in chosen:
        if s.family is None or s.family.draws >= draws:
            continue
        full = run_family(spec, s, seed, draws)
        few = family_result(s, full.members[:s.family.draws], seed)
        worst_few = {(r.metric, r.unit): badness(r) for r in few.rows if r.target}
        for sp in judged_spreads(full):
            w20 = max(abs(v) for v in sp.values) / (sp.target or 1.0)
            wn = worst_few.get((sp.metric, sp.unit), float("nan"))
            out.append((robot, s.name, sp.metric, str(s.family.draws), f"{wn:.3f}",
                        f"{w20:.3f}", "yes" if w20 <= SMALL else "NO"))
    return out


def main(argv: Sequence[str] | None = None) -> int:
    """Print the table; exit 1 if a family's spread is not small."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("robots", nargs="*", help="robots (default: every robot)")
    parser.add_argument("--scenario", help="one scenario of the one robot named")
    parser.add_argument("--seed", type=int, default=DEFAULT_SEED)
    parser.add_argument("--draws", type=int, default=DYNAMIC_DRAWS)
    args = parser.parse_args(argv)
    if args.scenario and len(args.robots) != 1:
        parser.error("--scenario takes exactly one robot")
    header = ("robot", "scenario", "metric", "N", "worst of N / target",
              f"worst of {args.draws} / target", f"small (<= {SMALL})")
    table = [header]
    t0 = time.perf_counter()
    for robot in args.robots or list(ROBOTS):
        table += rows(robot, args.scenario, args.seed, args.draws)
    widths = [max(len(r[i]) for r in table) for i in range(len(header))]
    for r in table:
        print("  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)))
    print(f"seed {args.seed}; {time.perf_counter() - t0:.1f} s")
    return 0 if all(r[-1] == "yes" for r in table[1:]) else 1


if __name__ == "__main__":
    raise SystemExit(main())
