"""The closed-loop scenario families, run member by member, worst per metric printed.

The scenarios are the registry's (:mod:`wmr_mujoco.loop.tasks.families` adds them to
every drivable robot); ``wmr validate`` judges them with the other scenarios. This prints
each family's figures alone::

    python -m wmr_mujoco.control.families [--robot NAME ...] [--seed S] [--draws N]

One Markdown row per scenario and metric: the worst member's value (largest ``|value| /
target``, or ``|value|`` without a target), the median over the members, the target and
whether every member met it.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from collections.abc import Sequence

import numpy as np

from wmr_mujoco.loop.tasks.families import loop_scenarios
from wmr_mujoco.robots import ROBOTS
from wmr_mujoco.validation.family import DEFAULT_SEED
from wmr_mujoco.validation.scenarios import Scenario


def family_rows(s: Scenario, seed: int, draws: int | None) -> list[str]:
    """The Markdown rows of one scenario's family (module docstring)."""
    assert s.family is not None and s.evaluate is not None
    members = [s.member(d) for d in s.family.sample(seed, s.key, draws)]
    results = [s.evaluate(m, None).metrics for m in members]
    rows = []
    for k, metric in enumerate(results[0]):
        values = np.array([r[k].value for r in results])
        target = metric.target
        scale = target.value if target is not None else 1.0
        worst = int(np.argmax(np.where(np.isfinite(values), np.abs(values) / scale, math.inf)))
        verdict = "" if target is None else (
            "pass" if all(abs(v) <= target.value for v in values) else "FAIL")
        rows.append(f"| {s.robot} | {s.name} | {metric.name} | {values[worst]:.4g} | "
                    f"{float(np.median(values)):.4g} | {metric.unit} | "
                    f"{'' if target is None else f'{target.value:g}'} | {verdict} |")
    return rows


def main(argv: Sequence[str] | None = None) -> int:
    """Run the families and print the table; exit 1 if a judged metric failed."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--robot", action="append", choices=sorted(ROBOTS),
                        help="robot to run (repeatable; default: all)")
    parser.add_argument("--seed", type=int, default=DEFAULT_SEED)
    parser.add_argument("--draws", type=int, default=None, help="members per family")
    args = parser.parse_args(argv)
    if args.seed < 0 or (args.draws is not None and not 1 <= args.draws <= 1000):
        parser.error("--seed must be >= 0 and --draws in [1, 1000]")
    print("| robot | scenario | metric | worst | median | unit | target | verdict |\n"
          "|---|---|---|---|---|---|---|---|", flush=True)
    failed = False
    for name in args.robot or list(ROBOTS):
        for s in loop_scenarios(ROBOTS[name]):
            t0 = time.monotonic()
            rows = family_rows(s, args.seed, args.draws)
            failed |= any(r.endswith("| FAIL |") for r in rows)
            print("\n".join(rows), flush=True)
            print(f"{s.key}: {time.monotonic() - t0:.0f} s", file=sys.stderr, flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
