"""Where an environment step's time goes: the layers above a bare ``mj_step`` loop.

``python -m wmr_mujoco.bench.env_ladder [--seconds S] [--repeats N] [ID ...]`` (default:
the light robots' ids, where the Python around the physics weighs most) replays the
scripted episode of :mod:`wmr_mujoco.bench.env_throughput` through loops that each add one
layer of the environment's step, and prints each loop's µs per step and what its layer
adds:

* ``bare``: ``data.ctrl[:] = u; mujoco.mj_step(model, data, frame_skip)``;
* ``physics``: :meth:`Stepper.advance <wmr_mujoco.envs.stepping.Stepper.advance>` (the
  command map, then the same timesteps split around the reading's ``mj_step1``);
* ``stepper``: :meth:`Stepper.step <wmr_mujoco.envs.stepping.Stepper.step>` (adds the
  divergence check and the snapshot: pose, twist, wheel rates);
* ``task``: the stepper, then the task's reward terms, outcome and observation block
  (:meth:`Task.evaluate_observe <wmr_mujoco.envs.tasks.base.Task.evaluate_observe>`);
* ``episode``: :meth:`Episode.advance <wmr_mujoco.envs.episode.Episode.advance>` (adds the
  info dict and the float32 observation);
* ``env``: ``env.step`` (adds the action's check).

Every loop runs the same physics after the same actions, in this process, timed in its CPU
time and taking turns (medians of ``--repeats`` runs of ``--seconds``): each layer's cost is
measured as it runs in a real step, right after the physics has filled the caches, which
is dearer than the same Python timed alone in a tight loop.
"""

from __future__ import annotations

import argparse
import statistics
from collections.abc import Callable, Sequence
from itertools import pairwise
from typing import Any

import gymnasium as gym
import mujoco

from wmr_mujoco.bench.env_throughput import SEED, check_ids, rate, record, replayer

#: The loops, each adding one layer to the one before (module docstring).
LAYERS = ("bare", "physics", "stepper", "task", "episode", "env")


def ladder_loops(env_id: str) -> tuple[dict[str, Callable[[int], float]], dict[str, Any]]:
    """The timed loops of :data:`LAYERS`, and the environment each steps (its own)."""
    rec = record(gym.make(env_id))
    actions = [a.tolist() for a in rec.actions]
    n = len(actions)
    envs = {name: gym.make(env_id).unwrapped for name in LAYERS}
    for e in envs.values():
        e.reset(seed=SEED)

    def restart(name: str) -> Callable[[], None]:
        return lambda: envs[name].reset(seed=SEED)

    bare = envs["bare"].robot
    model, data, skip = bare.model, bare.data, envs["bare"].frame_skip
    start = mujoco.MjData(model)
    mujoco.mj_copyData(start, model, data)
    physics, stepper = envs["physics"].episode.stepper, envs["stepper"].episode.stepper
    task_ep, episode = envs["task"].episode, envs["episode"].episode
    env = envs["env"]

    def bare_step(k: int) -> bool:
        data.ctrl[:] = rec.controls[k]
        mujoco.mj_step(model, data, skip)
        return False

    def task_step(k: int) -> bool:
        prev = task_ep.state
        task_ep.state = state = task_ep.stepper.step(rec.commands[k])
        _, success, failure, _ = task_ep.task.evaluate_observe(prev, state, actions[k],
                                                               task_ep.dt)
        return success or failure

    def env_step(k: int) -> bool:
        _, _, term, trunc, _ = env.step(rec.actions[k])
        return term or trunc

    steps: dict[str, Callable[[int], bool]] = {
        "bare": bare_step,
        "physics": lambda k: physics.advance(rec.commands[k]) or False,
        "stepper": lambda k: stepper.step(rec.commands[k]) and False,
        "task": task_step,
        "episode": lambda k: any(episode.advance(actions[k])[2:4]),
        "env": env_step}
    restarts = {name: restart(name) for name in LAYERS}
    restarts["bare"] = lambda: mujoco.mj_copyData(data, model, start)
    return {name: replayer(steps[name], restarts[name], n) for name in LAYERS}, envs


def ladder(env_id: str, seconds: float, repeats: int) -> dict[str, float]:
    """Median µs per step of each loop of :data:`LAYERS`."""
    runs, _ = ladder_loops(env_id)
    for run in runs.values():
        run(10)
    samples: dict[str, list[float]] = {name: [] for name in runs}
    for _ in range(repeats):
        for name, run in runs.items():
            samples[name].append(1e6 / rate(run, seconds))
    return {name: statistics.median(x) for name, x in samples.items()}


def table(rows: dict[str, dict[str, float]]) -> str:
    """Markdown: µs per step of each loop, and (in brackets) what its layer adds."""
    head = "| environment | " + " | ".join(LAYERS) + " | env / bare |"
    lines = [head, "|---|" + "---:|" * (len(LAYERS) + 1)]
    for env_id, us in rows.items():
        cells = [f"{us['bare']:.1f}"] + [
            f"{us[b]:.1f} (+{us[b] - us[a]:.1f})" for a, b in pairwise(LAYERS)]
        lines.append(f"| {env_id} | " + " | ".join(cells) +
                     f" | {100 * us['bare'] / us['env']:.0f} % |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    """Print the table (µs per step); exit 2 on bad arguments."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("ids", nargs="*", help="environment ids (default: the light robots)")
    parser.add_argument("--seconds", type=float, default=0.5)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args(argv)
    if not 0.05 <= args.seconds <= 30 or not 1 <= args.repeats <= 20:
        parser.error(f"--seconds {args.seconds} (valid: 0.05 to 30), --repeats "
                     f"{args.repeats} (1 to 20)")
    ids = check_ids(parser, args.ids) or ["wmr/Disc-GoToGoal-v0", "wmr/Disc-FollowPath-v0",
                                          "wmr/Bicycle-FollowPath-v0"]
    rows = {}
    for env_id in ids:
        rows[env_id] = ladder(env_id, args.seconds, args.repeats)
    print(table(rows))
    print(f"\nµs per step (in brackets: what the layer adds to the one before); medians of "
          f"{args.repeats} runs of {args.seconds:g} s, one process, CPU time.")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
