"""CPU seconds of ``wmr validate ROBOT`` before and after a change, in paired runs.

Usage: ``python scripts/cost_pair.py BEFORE_SRC ROBOT [ROBOT ...] [--rounds N]``

``BEFORE_SRC``: the ``src`` folder of a checkout of the code before the change (e.g.
``git worktree add /tmp/before main``: ``/tmp/before/src``). For each robot and round it
runs ``scripts/validate_cost.py ROBOT`` (one process, seed 0) with that code and then with
this checkout's, one after the other (the same load on a shared machine), prints both
CPU totals, and checks that the two reports hold the same figures
(``scripts/compare_reports.py``); then the median of the rounds per robot and their sum.
Exit status 0: every pair's reports the same; 1: not.
"""

from __future__ import annotations

import os
import re
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent


def cpu(src: str | None, robot: str, out: Path) -> float:
    """CPU seconds of one ``validate_cost.py`` run (``src``: the code to import; None: ours)."""
    env = dict(os.environ)
    script = HERE / "validate_cost.py"
    if src is not None:
        env["PYTHONPATH"] = src
        script = Path(src).parent / "scripts" / "validate_cost.py"
    done = subprocess.run([sys.executable, str(script), robot, "--out", str(out)], env=env,
                          capture_output=True, text=True, check=False)
    found = re.search(r": ([0-9.]+) CPU s in all", done.stdout)
    if found is None:
        raise SystemExit(f"{robot}: no CPU figure in the output:\n{done.stdout}{done.stderr}")
    return float(found.group(1))


def main(argv: list[str]) -> int:
    """Run the pairs; the exit status of the module docstring."""
    rounds = 1
    if "--rounds" in argv:
        k = argv.index("--rounds")
        rounds = int(argv[k + 1])
        argv = argv[:k] + argv[k + 2:]
    if len(argv) < 2 or rounds < 1:
        print(__doc__)
        return 2
    src, robots = argv[0], argv[1:]
    same = True
    medians: dict[str, tuple[float, float]] = {}
    with tempfile.TemporaryDirectory() as tmp:
        for robot in robots:
            pairs = []
            for r in range(rounds):
                before, after = Path(tmp) / f"{robot}-{r}-before", Path(tmp) / f"{robot}-{r}-after"
                pair = (cpu(src, robot, before), cpu(None, robot, after))
                check = subprocess.run([sys.executable, str(HERE / "compare_reports.py"),
                                        str(before), str(after)], capture_output=True,
                                       text=True, check=False)
                same &= check.returncode == 0
                print(f"{robot} round {r + 1}: {pair[0]:.1f} -> {pair[1]:.1f} CPU s; "
                      f"{check.stdout.strip()}", flush=True)
                pairs.append(pair)
            medians[robot] = (statistics.median(p[0] for p in pairs),
                              statistics.median(p[1] for p in pairs))
    for robot, (b, a) in medians.items():
        print(f"{robot:16s} {b:7.1f} -> {a:7.1f} CPU s (median of {rounds}; {a / b:.2f})")
    total = [sum(v[i] for v in medians.values()) for i in (0, 1)]
    print(f"{'sum':16s} {total[0]:7.1f} -> {total[1]:7.1f} CPU s")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
