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

``--vector N`` times the native vector environment's batched step instead, per world-step,
at ``N`` worlds (:data:`VECTOR_LAYERS`): ``bare`` (the bare loop over the N worlds),
``physics`` (:meth:`Worlds.push <wmr_mujoco.envs.worlds.Worlds.push>`: every world's
command and timesteps), ``read`` (adds :meth:`Worlds.read
<wmr_mujoco.envs.worlds.Worlds.read>`: every world's state into arrays), ``task`` (adds
the task's arrays step, :mod:`wmr_mujoco.envs.tasks.arrays`) and ``vector`` (``step`` of
the vector environment: adds the action check, observation, flags and infos).

Every loop runs the same physics after the same actions, in this process, timed in its CPU
time and taking turns (medians of ``--repeats`` rounds of runs of ``--seconds``, each round
timing the bare loop first and last: :func:`wmr_mujoco.bench.env_loops.paired`; the bare
figure is the median of the rounds' mean of the two): each layer's cost is
measured as it runs in a real step, right after the physics has filled the caches, which
is dearer than the same Python timed alone in a tight loop.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable, Sequence
from itertools import pairwise
from typing import Any

import gymnasium as gym
import numpy as np

from wmr_mujoco.bench import env_loops as el
from wmr_mujoco.bench.env_loops import SEED

#: The loops, each adding one layer to the one before (module docstring).
LAYERS = ("bare", "physics", "stepper", "task", "episode", "env")
#: The loops of the native vector environment's batched step (module docstring).
VECTOR_LAYERS = ("bare", "physics", "read", "task", "vector")


def vector_loops(env_id: str, worlds: int) -> dict[str, el.Run]:
    """The timed loops of :data:`VECTOR_LAYERS` at ``worlds`` worlds, each its own envs."""
    rec = el.record(gym.make(env_id))
    off = gym.vector.AutoresetMode.DISABLED
    # The batched path at any world count (the layers below are its own).
    vecs = {name: gym.make_vec(env_id, num_envs=worlds, autoreset_mode=off, batched=True)
            for name in VECTOR_LAYERS}
    for v in vecs.values():
        v.reset(seed=[SEED] * worlds)
    batch = [np.stack([a] * worlds).astype(float) for a in rec.actions]

    def read_step(k: int) -> bool:
        w = vecs["read"].engine.worlds
        w.push(batch[k])
        w.read()
        return False

    def task_step(k: int) -> bool:
        v = vecs["task"].engine
        v.worlds.push(batch[k])
        _, success, failure = v.tasks.step(v.worlds.read(), batch[k], v.dt, v._full)
        return bool(success.any() or failure.any())

    def vector_step(k: int) -> bool:
        _, _, term, trunc, _ = vecs["vector"].step(batch[k])
        return bool(term.any() or trunc.any())

    steps = {"physics": lambda k: vecs["physics"].engine.worlds.push(batch[k]) or False,
             "read": read_step, "task": task_step, "vector": vector_step}
    bare = [(e.robot.model, e.robot.data, e.frame_skip) for e in vecs["bare"].envs]
    return {"bare": el.bare_loop(bare, rec.controls),
            **{name: el.replayer(step, lambda v=vecs[name]: v.reset(seed=[SEED] * worlds),
                                 len(batch)) for name, step in steps.items()}}


def ladder_loops(env_id: str) -> tuple[dict[str, el.Run], dict[str, Any]]:
    """The timed loops of :data:`LAYERS`, and the environment each steps (its own)."""
    rec = el.record(gym.make(env_id))
    actions = [a.tolist() for a in rec.actions]
    n = len(actions)
    envs = {name: gym.make(env_id).unwrapped for name in LAYERS}
    for e in envs.values():
        e.reset(seed=SEED)
    physics, stepper = envs["physics"].episode.stepper, envs["stepper"].episode.stepper
    task_ep, episode = envs["task"].episode, envs["episode"].episode
    env = envs["env"]

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
        "physics": lambda k: physics.advance(rec.commands[k]) or False,
        "stepper": lambda k: stepper.step(rec.commands[k]) and False,
        "task": task_step,
        "episode": lambda k: any(episode.advance(actions[k])[2:4]),
        "env": env_step}
    bare = envs["bare"]
    runs = {"bare": el.bare_loop([(bare.robot.model, bare.robot.data, bare.frame_skip)],
                                 rec.controls),
            **{name: el.replayer(step, lambda e=envs[name]: e.reset(seed=SEED), n)
               for name, step in steps.items()}}
    return runs, envs


def ladder(env_id: str, seconds: float, repeats: int, worlds: int = 0) -> dict[str, float]:
    """Median µs per step of each loop of :data:`LAYERS` (paired rounds, module docstring).

    ``worlds`` > 0: µs per world-step of :data:`VECTOR_LAYERS` at that many worlds.
    """
    runs = vector_loops(env_id, worlds) if worlds else ladder_loops(env_id)[0]
    bare = runs.pop("bare")
    got = el.paired(bare, runs, seconds, repeats)  # steps/s of the loop (all its worlds)
    per = 1e6 / max(worlds, 1)
    return {"bare": per / got.bare, **{name: per / r for name, r in got.rates.items()}}


def table(rows: dict[str, dict[str, float]]) -> str:
    """Markdown: µs per step of each loop, and (in brackets) what its layer adds."""
    layers = VECTOR_LAYERS if "vector" in next(iter(rows.values())) else LAYERS
    head = "| environment | " + " | ".join(layers) + f" | {layers[-1]} / bare |"
    lines = [head, "|---|" + "---:|" * (len(layers) + 1)]
    for env_id, us in rows.items():
        cells = [f"{us['bare']:.1f}"] + [
            f"{us[b]:.1f} (+{us[b] - us[a]:.1f})" for a, b in pairwise(layers)]
        lines.append(f"| {env_id} | " + " | ".join(cells) +
                     f" | {100 * us['bare'] / us[layers[-1]]:.0f} % |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    """Print the table (µs per step); exit 2 on bad arguments."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("ids", nargs="*", help="environment ids (default: the light robots)")
    el.add_timing(parser, 0.5)
    parser.add_argument("--vector", type=int, default=0,
                        help="worlds of the native vector env (default 0: the single env)")
    args = parser.parse_args(argv)
    el.check_options(parser, args, ("--vector", args.vector, 0 <= args.vector <= 64, "0 to 64"))
    ids = el.check_ids(parser, args.ids) or ["wmr/Disc-GoToGoal-v0", "wmr/Disc-FollowPath-v0",
                                          "wmr/Bicycle-FollowPath-v0"]
    rows = {}
    for env_id in ids:
        rows[env_id] = ladder(env_id, args.seconds, args.repeats, args.vector)
    print(table(rows))
    per = f"world-step at {args.vector} worlds" if args.vector else "step"
    print(f"\nµs per {per} (in brackets: what the layer adds to the one before); medians of "
          f"{args.repeats} runs of {args.seconds:g} s, one process, CPU time.")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
