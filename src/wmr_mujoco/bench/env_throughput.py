"""Environment steps per second, one process, against a bare ``mj_step`` loop.

``python -m wmr_mujoco.bench.env_throughput [--seconds S] [--repeats N] [--vector N] [--all]
[ID ...]`` prints, for each Gymnasium environment (default: one GoToGoal per drivable robot,
and the Whipple bicycle's StayUpright; ``--all``: every id), the steps/s of

* ``env``: ``env.step`` of ``gymnasium.make(id)`` (whatever wrappers it registers), which
  steps the physics through the environments' recording-free loop
  (:mod:`wmr_mujoco.envs.stepping`);
* ``vector``: ``gymnasium.make_vec`` of ``--vector`` copies (``"sync"``: stepped one after
  the other in this process), counting every copy's steps;
* ``drive``: the stepping API, ``robot.step(command)`` (:mod:`wmr_mujoco.drive`, the same
  commands, no task; it records the history an environment does not need);
* ``bare``: ``data.ctrl[:] = u; mujoco.mj_step(model, data, frame_skip)`` on the same
  model, replaying the controls that the stepping API wrote,

and the ratios to the bare loop.

All four replay one recorded episode of the scripted controller
(:mod:`wmr_mujoco.envs.scripted`, the same seed every time): the actions as float32 (as a
policy gives them), so that the robot drives as a policy that solves the task would, and
episodes last as long as a solved one (a constant action would topple the Whipple bicycle
within half a second). Each loop starts the episode again at its end; the time of these
resets is left out of the steps/s (a reset settles the robot on the floor for half a
simulated second: physics that the bare loop does not do) and printed apart as
``reset ms``. All run in this one process and are timed in its CPU time (:data:`CLOCK`):
steps per second of one core. Each figure is the median of ``--repeats`` timed runs of
``--seconds`` after a warm-up, the loops taking turns.
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import gymnasium as gym
import mujoco
import numpy as np

import wmr_mujoco.envs as wenvs
from wmr_mujoco.envs.scripted import Scripted

#: The throughput goal: env steps/s over bare-loop steps/s.
GOAL = 0.7
#: Seed of the replayed episode.
SEED = 0
#: The clock: this process's CPU time, so that a figure is steps per second of one core
#: (wall time would also count the turns of other processes on a shared machine).
CLOCK = time.process_time


def rate(run: Callable[[int], float], seconds: float) -> float:
    """Steps/s of ``run(n)`` (``n`` steps, less the seconds of resets it returns).

    ``n`` grows until one run lasts ``seconds``.
    """
    n = 16
    while True:
        t0 = CLOCK()
        excluded = run(n)
        dt = CLOCK() - t0 - excluded
        if dt >= seconds:
            return n / dt
        n = max(2 * n, int(n * seconds / max(dt, 1e-6) * 1.1))


@dataclass(frozen=True)
class Recording:
    """One scripted episode: its actions (float32), robot commands and actuator controls."""

    actions: list[np.ndarray]
    commands: list[list[float]]
    controls: np.ndarray


def record(env: gym.Env, seed: int = SEED) -> Recording:
    """The scripted controller's episode of ``seed`` on ``env`` (a ``gymnasium.make`` env)."""
    episode = env.unwrapped.episode
    env.reset(seed=seed)
    ctrl = Scripted(episode)
    ctrl.reset()
    actions, commands, controls = [], [], []
    while True:
        a = ctrl.action(episode.state).astype(np.float32)
        _, _, term, trunc, _ = env.step(a)
        actions.append(a)
        commands.append(episode.command(a.tolist()))
        controls.append(episode.robot.data.ctrl.copy())
        if term or trunc:
            return Recording(actions, commands, np.array(controls))


def loops(env_id: str, vector: int
          ) -> tuple[dict[str, Callable[[int], float]], int, Callable[[], None]]:
    """The four timed loops of one environment (docstring), its frame skip and reset."""
    env = gym.make(env_id)
    rec = record(env)
    n = len(rec.actions)
    # The drive loop steps a robot of its own (the loops take turns: each keeps its place).
    inner = gym.make(env_id).unwrapped
    robot = inner.robot

    def replay(step: Callable[[int], bool], restart: Callable[[], None]
               ) -> Callable[[int], float]:
        state = {"k": 0}

        def run(steps: int) -> float:
            k, excluded = state["k"], 0.0
            for _ in range(steps):
                done = step(k)
                k += 1
                if done or k == n:
                    t0 = CLOCK()
                    restart()
                    excluded += CLOCK() - t0
                    k = 0
            state["k"] = k
            return excluded
        return run

    def env_step(k: int) -> bool:
        _, _, term, trunc, _ = env.step(rec.actions[k])
        return term or trunc

    vec = gym.make_vec(env_id, num_envs=vector, vectorization_mode="sync",
                       vector_kwargs={"autoreset_mode": gym.vector.AutoresetMode.DISABLED})
    batch = [np.stack([a] * vector) for a in rec.actions]

    def vec_step(k: int) -> bool:
        _, _, term, trunc, _ = vec.step(batch[k])
        return bool(term.any() or trunc.any())

    def drive_step(k: int) -> bool:
        robot.step(rec.commands[k])
        return False

    model = robot.model
    data = mujoco.MjData(model)
    inner.reset(seed=SEED)
    start = mujoco.MjData(model)  # the episode's first state
    mujoco.mj_copyData(start, model, robot.data)
    skip = inner.frame_skip

    def bare_step(k: int) -> bool:
        data.ctrl[:] = rec.controls[k]
        mujoco.mj_step(model, data, skip)
        return False

    runs = {"env": replay(env_step, lambda: env.reset(seed=SEED)),
            "vector": replay(vec_step, lambda: vec.reset(seed=[SEED] * vector)),
            "drive": replay(drive_step, lambda: inner.episode.reset(np.random.default_rng(SEED))),
            "bare": replay(bare_step, lambda: mujoco.mj_copyData(data, model, start))}
    env.reset(seed=SEED)
    vec.reset(seed=[SEED] * vector)
    mujoco.mj_copyData(data, model, start)
    return runs, skip, lambda: env.reset(seed=SEED)


def measure(env_id: str, seconds: float, repeats: int, vector: int = 4) -> dict[str, float]:
    """Median steps/s of the four loops (module docstring) and their ratios to bare."""
    runs, skip, reset = loops(env_id, vector)
    for run in runs.values():
        run(10)
    samples: dict[str, list[float]] = {name: [] for name in (*runs, "reset_ms")}
    for _ in range(repeats):
        for name, run in runs.items():
            samples[name].append(rate(run, seconds) * (vector if name == "vector" else 1))
        t0 = CLOCK()
        reset()
        samples["reset_ms"].append(1e3 * (CLOCK() - t0))
    out: dict[str, float] = {name: statistics.median(x) for name, x in samples.items()}
    for name in ("env", "vector", "drive"):
        out[f"{name}_ratio"] = out[name] / out["bare"]
    out["frame_skip"] = skip
    return out


def default_ids() -> list[str]:
    """One GoToGoal per robot, and StayUpright where that is the robot's task."""
    return [i for i in wenvs.ENV_IDS if "-GoToGoal-" in i or "-StayUpright-" in i]


def check_ids(parser: argparse.ArgumentParser, ids: Sequence[str]) -> list[str]:
    """``ids``, or ``parser.error`` (exit 2) naming the unknown ones and the valid ones."""
    bad = [i for i in ids if i not in wenvs.ENV_IDS]
    if bad:
        parser.error(f"unknown environment ids {bad}; valid: {', '.join(wenvs.ENV_IDS)}")
    return list(ids)


def table(rows: dict[str, dict[str, float]]) -> str:
    """The Markdown table of :func:`measure`'s figures, one row per environment."""
    lines = ["| environment | frame skip | env steps/s | vector steps/s | drive steps/s | "
             "bare mj_step steps/s | env / bare | vector / bare | drive / bare | reset ms |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for env_id, m in rows.items():
        lines.append(f"| {env_id} | {m['frame_skip']:.0f} | {m['env']:.0f} | {m['vector']:.0f}"
                     f" | {m['drive']:.0f} | {m['bare']:.0f} | {100 * m['env_ratio']:.0f} % | "
                     f"{100 * m['vector_ratio']:.0f} % | {100 * m['drive_ratio']:.0f} % | "
                     f"{m['reset_ms']:.1f} |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    """Print the table; exit 1 if a ratio is under the 70 % goal, 2 on bad arguments."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("ids", nargs="*", help="environment ids (default: one per robot)")
    parser.add_argument("--all", action="store_true", help="every environment id")
    parser.add_argument("--seconds", type=float, default=1.0)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--vector", type=int, default=4, help="copies in the vector env")
    args = parser.parse_args(argv)
    ids = check_ids(parser, args.ids) or (list(wenvs.ENV_IDS) if args.all else default_ids())
    if not 0.05 <= args.seconds <= 30 or not 1 <= args.repeats <= 20 or \
            not 1 <= args.vector <= 64:
        parser.error(f"--seconds {args.seconds} (valid: 0.05 to 30), --repeats "
                     f"{args.repeats} (1 to 20), --vector {args.vector} (1 to 64)")
    rows = {}
    for env_id in ids:
        rows[env_id] = measure(env_id, args.seconds, args.repeats, args.vector)
        print(table({env_id: rows[env_id]}).splitlines()[-1] if len(rows) > 1 else
              table(rows), flush=True)
    worst = min(m["env_ratio"] for m in rows.values())
    print(f"\nworst env / bare {100 * worst:.0f} % (goal >= {100 * GOAL:.0f} %), worst vector "
          f"/ bare {100 * min(m['vector_ratio'] for m in rows.values()):.0f} % "
          f"({args.vector} copies, sync); medians of {args.repeats} runs of {args.seconds:g} s,"
          " one process")
    return 0 if worst >= GOAL else 1


if __name__ == "__main__":
    raise SystemExit(main())
