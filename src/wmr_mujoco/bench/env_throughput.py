"""Environment steps per second, one process, against a bare ``mj_step`` loop.

``python -m wmr_mujoco.bench.env_throughput [--seconds S] [--repeats N] [ID ...]`` prints,
for each Gymnasium environment (default: one GoToGoal per drivable robot), the steps/s of

* ``env.step`` (``gymnasium.make``, its wrappers included) under a constant small action
  (resetting when an episode ends; the reset time counts),
* the stepping API alone, ``robot.step(command)`` (:mod:`wmr_mujoco.drive`, the same
  command, no task), which the environment calls once per step,
* the bare loop ``mujoco.mj_step(model, data, frame_skip)`` on the same model and state
  with constant controls,

and the ratios env/bare and drive/bare: the gap between the first two is the
environment's own cost (task, observation, reward), the rest the stepping API's readout.
All run in this one process (one core); each figure is the median of ``--repeats`` timed
runs of ``--seconds`` after a warm-up, interleaved so that load on a shared machine hits
all alike.
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections.abc import Callable, Sequence

import gymnasium as gym
import mujoco
import numpy as np

import wmr_mujoco.envs as wenvs

#: The constant normalised action (small: episodes run long, few resets).
ACTION = 0.05


def rate(run: Callable[[int], None], seconds: float) -> float:
    """Calls of ``run(n)`` per second: ``n`` doubled until one run lasts ``seconds``."""
    n = 16
    while True:
        t0 = time.perf_counter()
        run(n)
        dt = time.perf_counter() - t0
        if dt >= seconds:
            return n / dt
        n = max(2 * n, int(n * seconds / max(dt, 1e-6) * 1.1))


def measure(env_id: str, seconds: float, repeats: int) -> dict[str, float]:
    """Median env, drive and bare steps/s of one environment, and the ratios to bare."""
    env = gym.make(env_id)
    inner = env.unwrapped
    env.reset(seed=0)
    action = np.full(env.action_space.shape, ACTION, np.float32)
    command = inner.episode.command(action.astype(float))
    robot = inner.robot

    def env_steps(n: int) -> None:
        for _ in range(n):
            _, _, term, trunc, _ = env.step(action)
            if term or trunc:
                env.reset()

    def drive_steps(n: int) -> None:
        for _ in range(n):
            robot.step(command)

    model = inner.robot.model
    data = mujoco.MjData(model)
    data.qpos[:] = inner.robot.data.qpos
    data.ctrl[:] = inner.robot.data.ctrl
    skip = inner.frame_skip

    def bare_steps(n: int) -> None:
        for _ in range(n):
            mujoco.mj_step(model, data, skip)

    env_steps(10)
    bare_steps(10)
    envs, drives, bares = [], [], []
    for _ in range(repeats):
        envs.append(rate(env_steps, seconds))
        bares.append(rate(bare_steps, seconds))
        robot.reset(seed=0)
        drives.append(rate(drive_steps, seconds))
        env.reset(seed=0)
    env.close()
    e, d, b = (statistics.median(x) for x in (envs, drives, bares))
    return {"env": e, "drive": d, "bare": b, "ratio": e / b, "drive_ratio": d / b,
            "frame_skip": skip}


def main(argv: Sequence[str] | None = None) -> int:
    """Print the table; exit 1 if a ratio is under the 70 % goal, 2 on bad arguments."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("ids", nargs="*", help=f"environment ids (of {', '.join(wenvs.ENV_IDS)})")
    parser.add_argument("--seconds", type=float, default=1.0)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args(argv)
    ids = args.ids or [i for i in wenvs.ENV_IDS if "-GoToGoal-" in i or "-StayUpright-" in i]
    bad = [i for i in ids if i not in wenvs.ENV_IDS]
    if bad or not 0.05 <= args.seconds <= 30 or not 1 <= args.repeats <= 20:
        parser.error(f"unknown ids {bad} (valid: {', '.join(wenvs.ENV_IDS)}), or --seconds "
                     "outside [0.05, 30], or --repeats outside [1, 20]")
    print("| environment | frame skip | env steps/s | drive robot.step/s | bare mj_step "
          "loop steps/s | env / bare | drive / bare |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    worst = 1.0
    for env_id in ids:
        m = measure(env_id, args.seconds, args.repeats)
        worst = min(worst, m["ratio"])
        print(f"| {env_id} | {m['frame_skip']} | {m['env']:.0f} | {m['drive']:.0f} | "
              f"{m['bare']:.0f} | {100 * m['ratio']:.0f} % | {100 * m['drive_ratio']:.0f} % |",
              flush=True)
    print(f"\nworst ratio {100 * worst:.0f} % (goal >= 70 %); medians of {args.repeats} runs "
          f"of {args.seconds:g} s, one process")
    return 0 if worst >= 0.7 else 1


if __name__ == "__main__":
    raise SystemExit(main())
