"""The environment benchmarks' timed loops, their clock and their paired measurement.

:mod:`~wmr_mujoco.bench.env_throughput`, :mod:`~wmr_mujoco.bench.env_ladder` and
:mod:`~wmr_mujoco.bench.vector_paths` replay one recorded episode of the scripted
controller (:mod:`wmr_mujoco.envs.scripted`, seed :data:`SEED`) through loops that each
keep their place between timed runs (:func:`replayer`), and time them in this process's
CPU time (:data:`CLOCK`). This module holds what they share: the recording, the bare
``mj_step`` loop (:func:`bare_loop`), the vector environments' loop (:func:`vector_loop`),
the rate of a loop (:func:`rate`), the paired rounds (:func:`paired`) and the command-line
checks.

A paired measurement runs ``repeats`` rounds; each round times the bare loop first and
last and the other loops between, and a loop's ratio is the median over rounds of its
steps/s over the mean of its round's two bare runs::

    ratio = median_r [ rate_r / ((bare_r,first + bare_r,last) / 2) ]

so that a load that changes from round to round (a shared machine) cancels out of it.
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections.abc import Callable, Hashable, Mapping, Sequence
from dataclasses import dataclass
from typing import Generic, TypeVar

import gymnasium as gym
import mujoco
import numpy as np

import wmr_mujoco.envs as wenvs
from wmr_mujoco.envs.scripted import Scripted

#: Seed of the replayed episode.
SEED = 0
#: The clock: this process's CPU time, so that a figure is steps per second of one core
#: (wall time would also count the turns of other processes on a shared machine).
CLOCK = time.process_time
#: A timed loop: ``run(steps)`` steps and returns the seconds to leave out (resets).
Run = Callable[[int], float]
#: The vector environments of :func:`vector_loop`.
VECTOR_MODES = ("native", "serial", "batched", "sync")

K = TypeVar("K", bound=Hashable)


def rate(run: Run, seconds: float) -> float:
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


def replayer(step: Callable[[int], bool], restart: Callable[[], object], n: int) -> Run:
    """A timed loop: ``run(steps)`` calls ``step(k)`` along an ``n``-step episode.

    At the episode's end (or when ``step`` says it ended) it calls ``restart`` and starts
    again at ``k = 0``; ``run`` returns the seconds of those restarts (left out of the
    rate). Each loop keeps its place between runs.
    """
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


def bare_world(env_id: str) -> tuple[mujoco.MjModel, mujoco.MjData, int]:
    """A model, a data of its own at the episode's first state, and the frame skip."""
    inner = gym.make(env_id).unwrapped
    inner.reset(seed=SEED)
    data = mujoco.MjData(inner.robot.model)
    mujoco.mj_copyData(data, inner.robot.model, inner.robot.data)
    return inner.robot.model, data, inner.frame_skip


def bare_loop(worlds: Sequence[tuple[mujoco.MjModel, mujoco.MjData, int]],
              controls: np.ndarray) -> Run:
    """The bare loop: ``data.ctrl[:] = u; mj_step(model, data, skip)`` in every world.

    ``worlds``: ``(model, data, frame skip)``, each started again at its state when given.
    """
    starts = []
    for model, data, _ in worlds:
        starts.append(mujoco.MjData(model))
        mujoco.mj_copyData(starts[-1], model, data)

    def step(k: int) -> bool:
        for model, data, skip in worlds:
            data.ctrl[:] = controls[k]
            mujoco.mj_step(model, data, skip)
        return False

    def restart() -> None:
        for (model, data, _), start in zip(worlds, starts, strict=True):
            mujoco.mj_copyData(data, model, start)

    return replayer(step, restart, len(controls))


def vector_loop(env_id: str, n: int, actions: Sequence[np.ndarray], mode: str = "native"
                ) -> Run:
    """A timed loop of ``n`` worlds stepping ``actions`` (every world the same).

    ``mode``: ``native`` (``gymnasium.make_vec``: :mod:`wmr_mujoco.envs.vector`, its path
    by the number of worlds), ``serial`` or ``batched`` (the native one held to that
    path), ``sync`` (Gymnasium's generic sync vectorisation of n single environments).
    """
    if mode not in VECTOR_MODES:
        raise ValueError(f"mode {mode!r}; valid: {', '.join(VECTOR_MODES)}")
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


@dataclass(frozen=True)
class Paired(Generic[K]):
    """A paired measurement: medians of steps/s (every world's) and of the round ratios."""

    bare: float
    rates: dict[K, float]
    ratios: dict[K, float]


def paired(bare: Run, runs: Mapping[K, Run], seconds: float, repeats: int,
           worlds: Mapping[K, int] | None = None) -> Paired[K]:
    """The loops' steps/s against ``bare``'s, paired within rounds (module docstring).

    Each loop is warmed up first (10 steps). ``worlds``: the worlds a loop steps at once
    (its steps/s counts every world's; 1 where not given).
    """
    worlds = worlds or {}
    for run in (bare, *runs.values()):
        run(10)
    bares: list[float] = []
    rates: dict[K, list[float]] = {key: [] for key in runs}
    ratios: dict[K, list[float]] = {key: [] for key in runs}
    for _ in range(repeats):
        first = rate(bare, seconds)
        here = {key: rate(run, seconds) * worlds.get(key, 1) for key, run in runs.items()}
        bares.append(0.5 * (first + rate(bare, seconds)))
        for key, value in here.items():
            rates[key].append(value)
            ratios[key].append(value / bares[-1])
    return Paired(statistics.median(bares),
                  {key: statistics.median(v) for key, v in rates.items()},
                  {key: statistics.median(v) for key, v in ratios.items()})


def add_timing(parser: argparse.ArgumentParser, seconds: float) -> None:
    """The environment benchmarks' ``--seconds`` (one timed run) and ``--repeats`` (rounds)."""
    parser.add_argument("--seconds", type=float, default=seconds,
                        help="seconds of one timed run (0.05 to 30)")
    parser.add_argument("--repeats", type=int, default=3, help="timed rounds (1 to 20)")


def check_options(parser: argparse.ArgumentParser, args: argparse.Namespace,
                  *others: tuple[str, object, bool, str]) -> None:
    """``parser.error`` (exit 2) naming every bad option and its valid range.

    Checks ``--seconds`` and ``--repeats`` (:func:`add_timing`) and each of ``others``:
    ``(flag, value, whether it is valid, the valid range)``.
    """
    checks = (("--seconds", args.seconds, 0.05 <= args.seconds <= 30, "0.05 to 30"),
              ("--repeats", args.repeats, 1 <= args.repeats <= 20, "1 to 20"), *others)
    bad = [f"{flag} {value!r} (valid: {valid})" for flag, value, ok, valid in checks if not ok]
    if bad:
        parser.error(", ".join(bad))


def check_ids(parser: argparse.ArgumentParser, ids: Sequence[str]) -> list[str]:
    """``ids``, or ``parser.error`` (exit 2) naming the unknown ones and the valid ones."""
    bad = [i for i in ids if i not in wenvs.ENV_IDS]
    if bad:
        parser.error(f"unknown environment ids {bad}; valid: {', '.join(wenvs.ENV_IDS)}")
    return list(ids)
