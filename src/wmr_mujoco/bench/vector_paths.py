"""The native vector environment's steps/s by number of worlds, against a bare ``mj_step`` loop.

``python -m wmr_mujoco.bench.vector_paths [--seconds S] [--repeats N] [--sizes 4,8,16,64]
[--paths] ID ...`` prints, for each Gymnasium environment id and each number of worlds n,
the steps/s (every world's steps) over those of the bare loop with the same frame skip
(:mod:`wmr_mujoco.bench.env_throughput`: the same replayed scripted episode, the same
clock, resets left out) of

* ``native``: ``gymnasium.make_vec(id, num_envs=n)``, the native vector environment
  (:mod:`wmr_mujoco.envs.vector`, its path chosen by
  :data:`~wmr_mujoco.envs.vector.BATCHED_FROM`);
* ``sync``: Gymnasium's generic ``"sync"`` vectorisation of n single environments;
* with ``--paths``: ``serial`` and ``batched``, the native environment held to each of its
  two paths (:mod:`wmr_mujoco.envs.serial`, :mod:`wmr_mujoco.envs.batched`), and the
  crossover: the fewest worlds measured from which the batched path is the faster at that
  and every larger size (how :data:`~wmr_mujoco.envs.vector.BATCHED_FROM` was chosen).

Each figure is a paired ratio (:func:`wmr_mujoco.bench.env_loops.paired`): ``--repeats``
rounds of timed runs of ``--seconds``, the loops taking turns, each round timing the bare
loop first and last; a loop's ratio is the median over the rounds of its steps/s over its
round's bare steps/s, in this one process's CPU time. With ``--paths`` the last lines give
the crossover of every environment, their span and :data:`BATCHED_FROM` beside it.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence

import gymnasium as gym

from wmr_mujoco.bench import env_loops as el
from wmr_mujoco.envs.vector import BATCHED_FROM

#: The numbers of worlds measured by default.
SIZES = (1, 2, 4, 8, 12, 16, 24, 32, 64)


def measure(env_id: str, sizes: Sequence[int], modes: Sequence[str], seconds: float,
            repeats: int) -> dict[tuple[str, int], float]:
    """Paired ratios of every ``(mode, n)`` loop's steps/s (every world's) to the bare loop's."""
    rec = el.record(gym.make(env_id))
    runs = {(mode, n): el.vector_loop(env_id, n, rec.actions, mode)
            for n in sizes for mode in modes}
    bare = el.bare_loop([el.bare_world(env_id)], rec.controls)
    return el.paired(bare, runs, seconds, repeats, {key: key[1] for key in runs}).ratios


def crossover(ratios: dict[tuple[str, int], float], sizes: Sequence[int]) -> int | None:
    """The fewest worlds from which batched ≥ serial at every size measured; None: never."""
    best = None
    for n in sorted(sizes, reverse=True):
        if ratios[("batched", n)] < ratios[("serial", n)]:
            break
        best = n
    return best


def crossing_lines(crossings: dict[str, int | None], sizes: Sequence[int]) -> str:
    """Each environment's crossover, their span and :data:`BATCHED_FROM` beside it."""
    lines = [f"{env_id}: batched >= serial from {n} worlds on" if n is not None else
             f"{env_id}: batched slower than serial at {sizes[-1]} worlds"
             for env_id, n in crossings.items()]
    found = {env_id: n for env_id, n in crossings.items() if n is not None}
    if found:
        latest = max(found, key=found.get)
        lines.append(f"crossover over these {len(crossings)} environments: "
                     f"{min(found.values())} to {found[latest]} worlds (the latest: {latest}"
                     + (f"; {len(crossings) - len(found)} never" if len(found) < len(crossings)
                        else "") + f"); BATCHED_FROM = {BATCHED_FROM}")
    return "\n".join(lines)


def table(env_id: str, ratios: dict[tuple[str, int], float], sizes: Sequence[int],
          modes: Sequence[str]) -> str:
    """One Markdown table: a row per number of worlds, a column per loop (ratio to bare)."""
    lines = [f"{env_id}: steps/s over a bare mj_step loop", "",
             "| worlds | " + " | ".join(f"{m} / bare" for m in modes) + " |",
             "|---:|" + "---:|" * len(modes)]
    for n in sizes:
        lines.append(f"| {n} | " + " | ".join(f"{100 * ratios[(m, n)]:.0f} %" for m in modes)
                     + " |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    """Print the tables (and the crossovers with ``--paths``); exit 2 on bad input."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("ids", nargs="+", help="environment ids")
    el.add_timing(parser, 0.5)
    parser.add_argument("--sizes", default=",".join(map(str, SIZES)),
                        help="numbers of worlds, comma separated")
    parser.add_argument("--paths", action="store_true",
                        help="also each path alone (serial, batched) and their crossover")
    args = parser.parse_args(argv)
    ids = el.check_ids(parser, args.ids)
    try:
        sizes = sorted({int(v) for v in args.sizes.split(",")})
    except ValueError:
        sizes = []
    el.check_options(parser, args, ("--sizes", args.sizes,
                                 bool(sizes) and 1 <= sizes[0] <= sizes[-1] <= 64,
                                 "integers 1 to 64, comma separated"))
    modes = ["native", "sync"] + (["serial", "batched"] if args.paths else [])
    crossings = {}
    for env_id in ids:
        ratios = measure(env_id, sizes, modes, args.seconds, args.repeats)
        print(table(env_id, ratios, sizes, modes) + "\n", flush=True)
        if args.paths:
            crossings[env_id] = crossover(ratios, sizes)
    if args.paths:
        print(crossing_lines(crossings, sizes))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
