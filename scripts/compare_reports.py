"""Whether two ``wmr validate`` reports hold the same figures.

Usage: ``python scripts/compare_reports.py BEFORE_FOLDER AFTER_FOLDER``

Walks both ``validation.json`` files in step (the families' wall ``seconds`` left out)
and prints how many numbers they hold, the largest relative change of any of them, and
any difference of structure or text. Exit status 0: the same figures to 1e-9 relative
(the bar of a speed-up that must not change a result); 1: not.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

SKIP = ("seconds",)
TOLERANCE = 1e-9


def compare(a: object, b: object, path: str, out: dict) -> None:
    """Record in ``out`` the numbers seen, the largest relative change and other changes."""
    if isinstance(a, dict) and isinstance(b, dict):
        if set(a) != set(b):
            out["other"].append(f"{path}: keys differ")
            return
        for key in a:
            if key not in SKIP:
                compare(a[key], b[key], f"{path}/{key}", out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out["other"].append(f"{path}: {len(a)} items against {len(b)}")
            return
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            compare(x, y, f"{path}[{i}]", out)
    elif (isinstance(a, (int, float)) and isinstance(b, (int, float))
          and not isinstance(a, bool) and not isinstance(b, bool)):
        out["numbers"] += 1
        if a == b or (math.isnan(a) and math.isnan(b)):
            return
        if not (math.isfinite(a) and math.isfinite(b)):
            out["other"].append(f"{path}: {a} against {b}")
            return
        change = abs(a - b) / max(abs(a), abs(b))
        if change > out["worst"][0]:
            out["worst"] = (change, path, a, b)
    elif a != b:
        out["other"].append(f"{path}: {a!r} against {b!r}")


def main(argv: list[str]) -> int:
    """Compare the two folders' reports; the exit status of the module docstring."""
    if len(argv) != 2:
        print(__doc__)
        return 2
    a, b = (json.loads((Path(f) / "validation.json").read_text()) for f in argv)
    out: dict = {"numbers": 0, "worst": (0.0, None, None, None), "other": []}
    compare(a, b, "", out)
    change, path, x, y = out["worst"]
    print(f"{out['numbers']} numbers; largest relative change {change:.3g}"
          + (f" at {path} ({x!r} against {y!r})" if path else "")
          + f"; {len(out['other'])} other differences")
    for line in out["other"][:20]:
        print("  " + line)
    return 0 if change <= TOLERANCE and not out["other"] else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
