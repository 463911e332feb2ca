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

Each figure is the median of ``--repeats`` timed runs of ``--seconds``, the loops taking
turns, in this one process's CPU time.
"""

from __future__ import annotations

import argparse
import statistics
from collections.abc import Callable, Sequence

import gymnasium as gym
import mujoco
import numpy as np

from wmr_mujoco.bench.env_throughput import (
    SEED,
    add_timing,
    check_ids,
    check_options,
    rate,
    record,
    replayer,
)

#: The numbers of worlds measured by default.
SIZES = (1, 2, 4, 8, 12, 16, 24, 32, 64)


def vector_loop(env_id: str, n: int, actions: list[np.ndarray], mode: str
                ) -> Callable[[int], float]:
    """A timed loop (:func:`replayer`) of ``n`` worlds: ``mode`` native, serial, batched, sync."""
    off = gym.vector.AutoresetMode.DISABLED  # the loop restarts the episode itself
    if mode == "sync":
        vec = gym.make_vec(env_id, num_envs=n, vectorization_mode="sync",
                           vector_kwargs={"autoreset_mode": off})
    else:
        kwargs = {} if mode == "native" else {"batched": mode == "batched"}
        vec = gym.make_vec(env_id, num_envs=n, autoreset_mode=off, **kwargs)
    batch = [np.stack([a] * n) for a in actions]
    vec.reset(seed=[SEED] * n)

    def step(k: int) -> bool:
        _, _, term, trunc, _ = vec.step(batch[k])
        return bool(term.any() or trunc.any())

    return replayer(step, lambda: vec.reset(seed=[SEED] * n), len(actions))


def bare_loop(env_id: str, controls: np.ndarray) -> Callable[[int], float]:
    """The bare loop: the recorded controls and ``mj_step(frame_skip)`` on the same model."""
    inner = gym.make(env_id).unwrapped
    inner.reset(seed=SEED)
    model, skip = inner.robot.model, inner.frame_skip
    start = mujoco.MjData(model)
    mujoco.mj_copyData(start, model, inner.robot.data)
    data = mujoco.MjData(model)
    mujoco.mj_copyData(data, model, start)

    def step(k: int) -> bool:
        data.ctrl[:] = controls[k]
        mujoco.mj_step(model, data, skip)
        return False

    return replayer(step, lambda: mujoco.mj_copyData(data, model, start), len(controls))


def measure(env_id: str, sizes: Sequence[int], modes: Sequence[str], seconds: float,
            repeats: int) -> dict[tuple[str, int], float]:
    """Median steps/s of every ``(mode, n)`` loop over the bare loop's (the ratios)."""
    rec = record(gym.make(env_id))
    runs = {("bare", 1): bare_loop(env_id, rec.controls)}
    for n in sizes:
        for mode in modes:
            runs[(mode, n)] = vector_loop(env_id, n, rec.actions, mode)
    for run in runs.values():
        run(10)
    samples: dict[tuple[str, int], list[float]] = {key: [] for key in runs}
    for _ in range(repeats):
        for key, run in runs.items():
            samples[key].append(rate(run, seconds) * key[1])
    bare = statistics.median(samples[("bare", 1)])
    return {key: statistics.median(v) / bare for key, v in samples.items() if key[0] != "bare"}


def crossover(ratios: dict[tuple[str, int], float], sizes: Sequence[int]) -> int | None:
    """The fewest worlds from which batched ≥ serial at every size measured; None: never."""
    best = None
    for n in sorted(sizes, reverse=True):
        if ratios[("batched", n)] < ratios[("serial", n)]:
            break
        best = n
    return best


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
    add_timing(parser, 0.5)
    parser.add_argument("--sizes", default=",".join(map(str, SIZES)),
                        help="numbers of worlds, comma separated")
    parser.add_argument("--paths", action="store_true",
                        help="also each path alone (serial, batched) and their crossover")
    args = parser.parse_args(argv)
    ids = check_ids(parser, args.ids)
    try:
        sizes = sorted({int(v) for v in args.sizes.split(",")})
    except ValueError:
        sizes = []
    check_options(parser, args, ("--sizes", args.sizes,
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
        for env_id, n in crossings.items():
            print(f"{env_id}: batched >= serial from {n} worlds on" if n is not None else
                  f"{env_id}: batched slower than serial at {sizes[-1]} worlds")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
