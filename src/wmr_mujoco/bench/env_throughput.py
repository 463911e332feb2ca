"""Environment steps per second, one process, against a bare ``mj_step`` loop.

``python -m wmr_mujoco.bench.env_throughput [--seconds S] [--repeats N] [--vector N] [--all]
[ID ...]`` prints, for each Gymnasium environment (default: one GoToGoal per drivable robot,
and the Whipple bicycle's StayUpright; ``--all``: every id), the steps/s of

* ``env`` (the single env): ``env.step`` of ``gymnasium.make(id)`` (whatever wrappers it
  registers), which steps the physics through the environments' recording-free loop
  (:mod:`wmr_mujoco.envs.stepping`);
* ``vector``, ``vector16``, ``vector64``: ``gymnasium.make_vec`` of ``--vector``, 16 and 64
  worlds, the native vector environment (:mod:`wmr_mujoco.envs.vector`: below
  ``BATCHED_FROM`` worlds each world through its single environment, from it on every
  world's physics, then the reading, task and bookkeeping of all worlds at once on arrays),
  counting every world's steps. The goal (:data:`GOAL`) is judged on 16 worlds
  (:data:`JUDGED`); ``python -m wmr_mujoco.bench.vector_paths`` gives every world count;
* ``sync``: the same through Gymnasium's generic ``"sync"`` vectorisation (n single
  environments stepped one after the other by :class:`gymnasium.vector.SyncVectorEnv`);
* ``drive``: the stepping API, ``robot.step(command)`` (:mod:`wmr_mujoco.drive`, the same
  commands, no task; it records the history an environment does not need);
* ``bare``: ``data.ctrl[:] = u; mujoco.mj_step(model, data, frame_skip)`` on the same
  model, replaying the controls that the stepping API wrote,

and the ratios to the bare loop.

All five replay one recorded episode of the scripted controller
(:mod:`wmr_mujoco.envs.scripted`, the same seed every time): the actions as float32 (as a
policy gives them), so that the robot drives as a policy that solves the task would, and
episodes last as long as a solved one (a constant action would topple the Whipple bicycle
within half a second). Each loop starts the episode again at its end; the time of these
resets is left out of the steps/s (a reset settles the robot on the floor for half a
simulated second: physics that the bare loop does not do) and printed apart as
``reset ms``. All run in this one process and are timed in its CPU time: steps per
second of one core. Each steps/s figure is the median of ``--repeats`` rounds of timed
runs of ``--seconds`` after a warm-up, the loops taking turns; each ratio is the median
over the rounds of the ratio within a round (the bare loop timed first and last in it),
so that a load that changes from round to round cancels out of the ratio
(:func:`wmr_mujoco.bench.env_loops.paired`).
"""

from __future__ import annotations

import argparse
import statistics
from collections.abc import Callable, Sequence

import gymnasium as gym
import numpy as np

import wmr_mujoco.envs as wenvs
from wmr_mujoco.bench import env_loops as el

#: The throughput goal: native vector env steps/s (every world's steps) over bare-loop
#: steps/s, judged at :data:`JUDGED` worlds.
GOAL = 0.7
#: The number of worlds at which the goal is judged; the table also gives 64.
JUDGED = 16
#: The vector sizes always measured beside ``--vector``.
SIZES = (16, 64)


def vector_sizes(vector: int) -> dict[str, int]:
    """The native vector loops: ``vector`` (the ``--vector`` worlds) and ``vector<n>``."""
    return {"vector": vector, **{f"vector{n}": n for n in SIZES}}

def loops(env_id: str, vector: int
          ) -> tuple[dict[str, el.Run], int, Callable[[], object]]:
    """The five timed loops of one environment (docstring), its frame skip and reset."""
    env = gym.make(env_id)
    rec = el.record(env)
    n = len(rec.actions)
    # The drive loop steps a robot of its own (the loops take turns: each keeps its place).
    inner = gym.make(env_id).unwrapped
    inner.reset(seed=el.SEED)
    robot = inner.robot

    def env_step(k: int) -> bool:
        _, _, term, trunc, _ = env.step(rec.actions[k])
        return term or trunc

    def drive_step(k: int) -> bool:
        robot.step(rec.commands[k])
        return False

    world = el.bare_world(env_id)
    runs = {"env": el.replayer(env_step, lambda: env.reset(seed=el.SEED), n),
            **{name: el.vector_loop(env_id, size, rec.actions)
               for name, size in vector_sizes(vector).items()
               if name == "vector" or size != vector},  # --vector 16: timed once
            "sync": el.vector_loop(env_id, vector, rec.actions, "sync"),
            "drive": el.replayer(drive_step, lambda: inner.episode.reset(
                np.random.default_rng(el.SEED)), n),
            "bare": el.bare_loop([world], rec.controls)}
    env.reset(seed=el.SEED)
    return runs, world[2], lambda: env.reset(seed=el.SEED)


def measure(env_id: str, seconds: float, repeats: int, vector: int = 4) -> dict[str, float]:
    """Median steps/s of the five loops (module docstring) and their ratios to bare.

    Paired rounds (:func:`~wmr_mujoco.bench.env_loops.paired`): each times the bare loop
    first and last and the other loops between; a loop's ratio is the median over rounds
    of its steps/s over the mean of its round's two bare runs. Then ``repeats`` resets of
    the single environment, timed apart (``reset_ms``, their median).
    """
    runs, skip, reset = loops(env_id, vector)
    bare = runs.pop("bare")
    got = el.paired(bare, runs, seconds, repeats, {**vector_sizes(vector), "sync": vector})
    resets = []
    for _ in range(repeats):
        t0 = el.CLOCK()
        reset()
        resets.append(1e3 * (el.CLOCK() - t0))
    out: dict[str, float] = {"bare": got.bare, **got.rates, "reset_ms": statistics.median(resets)}
    out.update({f"{name}_ratio": ratio for name, ratio in got.ratios.items()})
    for name in vector_sizes(vector):
        if name not in out:  # the --vector loop's size
            out[name], out[f"{name}_ratio"] = out["vector"], out["vector_ratio"]
    out["frame_skip"] = skip
    return out


def default_ids() -> list[str]:
    """One GoToGoal per robot, and StayUpright where that is the robot's task."""
    return [i for i in wenvs.ENV_IDS if "-GoToGoal-" in i or "-StayUpright-" in i]


def table(rows: dict[str, dict[str, float]]) -> str:
    """The Markdown table of :func:`measure`'s figures, one row per environment.

    ``single env``: ``gymnasium.make(id)``; ``vector n``: the native vector environment of n
    worlds (``--vector``, 16, 64), every world's steps counted; ``sync``: Gymnasium's sync
    vectorisation of ``--vector`` single environments.
    """
    lines = ["| environment | frame skip | bare mj_step steps/s | single env steps/s | vector "
             "(--vector) steps/s | vector 16 steps/s | single env / bare | vector (--vector) "
             "/ bare | vector 16 / bare | vector 64 / bare | sync / bare | drive / bare | "
             "reset ms |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for env_id, m in rows.items():
        pct = " | ".join(f"{100 * m[k + '_ratio']:.0f} %" for k in (
            "env", "vector", "vector16", "vector64", "sync", "drive"))
        lines.append(f"| {env_id} | {m['frame_skip']:.0f} | {m['bare']:.0f} | {m['env']:.0f} | "
                     f"{m['vector']:.0f} | {m['vector16']:.0f} | {pct} | {m['reset_ms']:.1f} |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    """Print the table; exit 1 if a vector ratio at 16 worlds misses the goal, 2: bad input."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("ids", nargs="*", help="environment ids (default: one per robot)")
    parser.add_argument("--all", action="store_true", help="every environment id")
    el.add_timing(parser, 1.0)
    parser.add_argument("--vector", type=int, default=4, help="copies in the vector env")
    args = parser.parse_args(argv)
    ids = el.check_ids(parser, args.ids) or (list(wenvs.ENV_IDS) if args.all else default_ids())
    el.check_options(parser, args, ("--vector", args.vector, 1 <= args.vector <= 64, "1 to 64"))
    rows = {}
    for env_id in ids:
        rows[env_id] = measure(env_id, args.seconds, args.repeats, args.vector)
        print(table({env_id: rows[env_id]}).splitlines()[-1] if len(rows) > 1 else
              table(rows), flush=True)
    print("\n" + summary(rows, args.vector, args.repeats, args.seconds))
    return 0 if worst(rows) >= GOAL else 1


def worst(rows: dict[str, dict[str, float]]) -> float:
    """The worst native vector / bare ratio at :data:`JUDGED` worlds (the judged figure)."""
    return min(m[f"vector{JUDGED}_ratio"] for m in rows.values())


def summary(rows: dict[str, dict[str, float]], vector: int, repeats: int,
            seconds: float) -> str:
    """The worst ratio of each loop against :data:`GOAL`, one line."""
    def low(key: str) -> str:
        ratio, env_id = min((m[key], i) for i, m in rows.items())
        return f"{100 * ratio:.0f} % ({env_id})"

    return (f"worst native vector / bare at {JUDGED} worlds {low(f'vector{JUDGED}_ratio')}: "
            f"the judged figure, goal >= {100 * GOAL:.0f} %. Worst at 64 worlds "
            f"{low('vector64_ratio')}, at {vector} worlds {low('vector_ratio')}; single env / "
            f"bare {low('env_ratio')}; sync / bare {low('sync_ratio')} (Gymnasium's sync "
            f"vectorisation of {vector}, for comparison). "
            f"{repeats} rounds of {seconds:g} s runs, ratios paired within a round (medians), "
            "one process, CPU time.")

if __name__ == "__main__":
    raise SystemExit(main())
