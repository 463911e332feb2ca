"""Scripted solvability: success rate of the scripted controllers on every task.

``python -m wmr_mujoco.bench.env_success [--episodes N] [--seed S] [ID ...]`` runs, for each
Gymnasium environment (default: all), ``N`` seeded episodes (seeds ``S .. S+N-1``) of the
scripted controller of :mod:`wmr_mujoco.envs.scripted` in the MuJoCo physics, and prints
the success rate with the Wilson 95 % lower bound and the seeds that failed. The goal is
a success rate of at least 95 %; the exit code is 1 if a rate is below it.
"""

from __future__ import annotations

import argparse
import math
import time
from collections.abc import Sequence

import gymnasium as gym
import numpy as np

import wmr_mujoco.envs as wenvs
from wmr_mujoco.bench.env_loops import check_ids
from wmr_mujoco.envs.scripted import run_episode

#: Required success rate.
GOAL = 0.95


def wilson_lower(k: int, n: int, z: float = 1.96) -> float:
    """Wilson score lower bound of a binomial proportion ``k / n``."""
    p = k / n
    centre = p + z * z / (2 * n)
    spread = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    return (centre - spread) / (1 + z * z / n)


def success_rate(env_id: str, episodes: int, seed: int) -> dict[str, object]:
    """Successes, episodes, failed seeds and seconds of the scripted controller on ``env_id``."""
    env = gym.make(env_id)
    episode = env.unwrapped.episode
    failed = []
    t0 = time.perf_counter()
    for s in range(seed, seed + episodes):
        ok, _ = run_episode(episode, np.random.default_rng(s))
        if not ok:
            failed.append(s)
    env.close()
    return {"successes": episodes - len(failed), "episodes": episodes, "failed": failed,
            "seconds": time.perf_counter() - t0}


def row(env_id: str, r: dict[str, object]) -> str:
    """One Markdown table row of :func:`success_rate`'s figures."""
    k, n, failed = r["successes"], r["episodes"], r["failed"]
    shown = ", ".join(map(str, failed[:10])) + (" ..." if len(failed) > 10 else "")
    return (f"| {env_id} | {k}/{n} | {100 * k / n:.1f} % | {100 * wilson_lower(k, n):.1f} % | "
            f"{shown or '-'} | {r['seconds']:.0f} |")


HEADER = ("| environment | successes | rate | Wilson 95 % lower bound | failed seeds | s |\n"
          "|---|---:|---:|---:|---|---:|")


def main(argv: Sequence[str] | None = None) -> int:
    """Print the table; exit 1 if a rate is below :data:`GOAL`, 2 on bad arguments."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("ids", nargs="*", help="environment ids (default: all)")
    parser.add_argument("--episodes", type=int, default=100)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    ids = check_ids(parser, args.ids) or list(wenvs.ENV_IDS)
    if not 1 <= args.episodes <= 10_000 or args.seed < 0:
        parser.error(f"--episodes {args.episodes} (valid: 1 to 10000), --seed {args.seed} "
                     "(valid: >= 0)")
    print(HEADER)
    worst = 1.0
    for env_id in ids:
        r = success_rate(env_id, args.episodes, args.seed)
        worst = min(worst, r["successes"] / args.episodes)
        print(row(env_id, r), flush=True)
    print(f"\nworst success rate {100 * worst:.1f} % (goal >= {100 * GOAL:.0f} %); seeds "
          f"{args.seed}..{args.seed + args.episodes - 1}")
    return 0 if worst >= GOAL else 1


if __name__ == "__main__":
    raise SystemExit(main())
