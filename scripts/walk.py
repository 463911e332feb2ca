"""The walk of one ``wmr`` command through the package: stays, files, climbs.

Usage: ``python scripts/walk.py validate diffdrive --scenario "straight"``

Every call from one module of :mod:`wmr_mujoco` into another is an edge of the walk
(import-time execution left out); the *route* is the modules in the order control first
enters them. A *climb* is an edge from a module of a lower layer into one of a higher
layer (a callback the caller was handed, such as an adapter of the ``RobotSpec``: the
layers' imports never run up, see ``tests/test_layers.py``). Prints the route, the
number of distinct edges and climbs, and the modules by how many calls entered them
(loops over time steps repeat the same edges).
"""

from __future__ import annotations

import collections
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from test_layers import PACKAGE, RANK, layer_of, module_name  # noqa: E402


def main(argv: list[str]) -> int:
    """Run ``wmr argv`` in this process under the tracer and print its walk."""
    from wmr_mujoco import cli

    package = str(PACKAGE)
    route: list[str] = []
    edges: dict[tuple[str, str], int] = {}
    entered: collections.Counter[str] = collections.Counter()
    names: dict[str, str] = {}

    def name_of(filename: str) -> str | None:
        if not filename.startswith(package):
            return None
        if filename not in names:
            names[filename] = module_name(Path(filename))
        return names[filename]

    def tracer(frame, event, arg):
        if event != "call" or frame.f_code.co_name == "<module>" or frame.f_back is None:
            return
        here = name_of(frame.f_code.co_filename)
        caller = name_of(frame.f_back.f_code.co_filename)
        if here is None or caller is None or here == caller:
            return
        entered[here] += 1
        if here not in route:
            route.append(here)
        edges[caller, here] = edges.get((caller, here), 0) + 1

    sys.setprofile(tracer)
    try:
        code = cli.main(argv)
    finally:
        sys.setprofile(None)
    climbs = [e for e in edges if RANK[layer_of(e[1])] > RANK[layer_of(e[0])]]
    print(f"wmr {' '.join(argv)}: exit {code}")
    print(f"route: {len(route)} modules, {len(edges)} distinct edges, "
          f"{len(climbs)} climbs (callbacks into a higher layer)")
    for caller, callee in climbs:
        print(f"  climb: {caller} -> {callee}  ({edges[caller, callee]} calls)")
    for name in route:
        print(f"  {entered[name]:7d} calls into {name}  [{layer_of(name)}]")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
