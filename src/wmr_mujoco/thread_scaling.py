"""How batched ``mujoco.rollout`` scales from one thread to all cores, against the machine.

A batch of identical open-loop rollouts (the robot cruising on its first validation
scenario's inputs) is timed on one thread and on all cores, alternately, and the speedup
is the median of the per-pair ratios ``t₁ / t_N``. Each rollout is sized to take about
``target_s`` seconds on one thread, so thread start-up and scheduling jitter are small
against the work, and its output arrays are allocated once (page faults would otherwise
be timed too).

The machine's own ceiling is measured the same way with processes instead of threads:
one process runs the single-thread batch alone, then ``N`` processes run it at once
(started together at a barrier); the ceiling is ``N t_alone / max(t_together)``. Threads
sharing one process should do no better than processes sharing nothing, so it is the
reference for the thread speedup, measured in the same run and as noisy as it; on a
virtual machine it is often well below ``N`` (shared caches, memory bandwidth, clock
boost, the hypervisor's other guests).
"""

from __future__ import annotations

import multiprocessing as mp
import os
import queue
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import mujoco
import numpy as np
from mujoco import rollout

from wmr_mujoco.loading import load
from wmr_mujoco.registry import get_spec

#: Steps per rollout in a batch.
NSTEP = 1000
#: Wall time one batch should take on one thread, s.
TARGET_S = 0.4


def driving_controls(model: mujoco.MjModel, robot: str) -> np.ndarray:
    """Steady controls of the robot's first validation scenario (its cruising inputs)."""
    from wmr_mujoco.scenarios import scenarios_for
    from wmr_mujoco.validation import make_adapter

    scenario = scenarios_for([robot])[0]
    adapter = make_adapter(scenario, model)
    x0 = np.zeros(len(adapter.state_names))
    return np.asarray(adapter.controls(scenario.input_at(scenario.duration), x0))


@dataclass
class Batch:
    """Identical rollouts of one robot from a settled, cruising state."""

    model: mujoco.MjModel
    initial: np.ndarray  # (nbatch, nstate)
    controls: np.ndarray  # (nbatch, nstep, nu)
    state: np.ndarray  # output, (nbatch, nstep, nstate)
    sensordata: np.ndarray  # output, (nbatch, nstep, nsensordata)

    @property
    def steps(self) -> int:
        """Steps in the whole batch."""
        return self.controls.shape[0] * self.controls.shape[1]

    def runner(self, nthread: int) -> Callable[[], None]:
        """A function that rolls the batch out on ``nthread`` threads (1: calling thread)."""
        if nthread < 1:
            raise ValueError(f"nthread = {nthread!r}; must be >= 1")
        datas = [mujoco.MjData(self.model) for _ in range(nthread)]

        def run() -> None:
            rollout.rollout(self.model, datas if nthread > 1 else datas[0], self.initial,
                            self.controls, state=self.state, sensordata=self.sensordata,
                            persistent_pool=nthread > 1)
        return run


def make_batch(robot: str, nbatch: int, nstep: int = NSTEP) -> Batch:
    """``nbatch`` rollouts of ``nstep`` steps of ``robot`` at its default settings."""
    if nbatch < 1 or nstep < 1:
        raise ValueError(f"nbatch = {nbatch!r}, nstep = {nstep!r}; both must be >= 1")
    model = load(robot)
    data = mujoco.MjData(model)
    data.ctrl[:] = driving_controls(model, robot)
    for _ in range(200):  # settle and get going
        mujoco.mj_step(model, data)
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    size = mujoco.mj_stateSize(model, spec)
    state0 = np.zeros(size)
    mujoco.mj_getState(model, data, state0, spec)
    return Batch(model, np.tile(state0, (nbatch, 1)),
                 np.tile(data.ctrl, (nbatch, nstep, 1)), np.empty((nbatch, nstep, size)),
                 np.empty((nbatch, nstep, model.nsensordata)))


def sized_batch(robot: str, threads: int, target_s: float = TARGET_S) -> Batch:
    """A batch that takes about ``target_s`` on one thread, a multiple of ``threads`` long."""
    probe = make_batch(robot, 2)
    run = probe.runner(1)
    run()
    t0 = time.perf_counter()
    run()
    per_rollout = (time.perf_counter() - t0) / 2
    nbatch = max(2, round(target_s / per_rollout / threads)) * threads
    return make_batch(robot, nbatch)


def _timed(fn: Callable[[], None]) -> float:
    t0 = time.perf_counter()
    fn()
    return time.perf_counter() - t0


def paired_rounds(pairs: dict[str, tuple[Callable[[], None], Callable[[], None]]],
                  rounds: int, warmup: bool = True) -> dict[str, tuple[float, float, float]]:
    """Per key, median times of ``slow`` and ``fast`` and the median of per-pair ratios.

    Each round runs every key's ``slow`` then ``fast``, so the machine's drifts in load
    fall on both alike and on every key alike (after one warm-up of each, unless
    ``warmup`` is False).
    """
    if rounds < 1:
        raise ValueError(f"rounds = {rounds!r}; must be >= 1")
    if warmup:
        for slow, fast in pairs.values():
            slow()
            fast()
    times: dict[str, tuple[list[float], list[float]]] = {k: ([], []) for k in pairs}
    for _ in range(rounds):
        for key, (slow, fast) in pairs.items():
            times[key][0].append(_timed(slow))
            times[key][1].append(_timed(fast))
    return {k: (float(np.median(ts)), float(np.median(tf)),
                float(np.median(np.divide(ts, tf)))) for k, (ts, tf) in times.items()}


def paired_ratio(slow: Callable[[], None], fast: Callable[[], None], rounds: int,
                 warmup: bool = True) -> tuple[float, float, float]:
    """:func:`paired_rounds` for one pair."""
    return paired_rounds({"": (slow, fast)}, rounds, warmup)[""]


def thread_speedups(robots: Sequence[str], rounds: int, threads: int | None = None,
                    target_s: float = TARGET_S) -> dict[str, dict[str, float]]:
    """Per robot, rollout steps/s on one thread and on ``threads``, and the speedup.

    ``threads`` defaults to all cores; the speedup is the median of ``rounds`` pairs,
    interleaved across the robots (:func:`paired_rounds`).
    """
    threads = threads or os.cpu_count() or 1
    batches = {r: sized_batch(r, threads, target_s) for r in robots}
    timed = paired_rounds({r: (b.runner(1), b.runner(threads)) for r, b in batches.items()},
                          rounds)
    out = {}
    for robot, (t1, tn, speedup) in timed.items():
        b = batches[robot]
        dt = b.model.opt.timestep
        out[robot] = {"nbatch": b.controls.shape[0], "threads": threads,
                      "rollout1_steps_per_s": b.steps / t1,
                      "rollout1_rtf": b.steps * dt / t1,
                      "rolloutN_steps_per_s": b.steps / tn, "rollout_speedup": speedup}
    return out


def _ceiling_worker(rank: int, nbatch: dict[str, int], rounds: int,
                    barrier: mp.synchronize.Barrier, results: mp.Queue) -> None:
    runs = {robot: make_batch(robot, n).runner(1) for robot, n in nbatch.items()}
    for run in runs.values():
        run()
    alone: dict[str, list[float]] = {r: [] for r in runs}
    together: dict[str, list[float]] = {r: [] for r in runs}
    for _ in range(rounds):
        for robot, run in runs.items():
            barrier.wait()
            if rank == 0:
                alone[robot].append(_timed(run))
            barrier.wait()
            together[robot].append(_timed(run))
    results.put((rank, alone, together))


def process_ceilings(nbatch: dict[str, int], rounds: int, processes: int | None = None
                     ) -> dict[str, float]:
    """Per robot, the median of ``N t_alone / max(t_together)`` over ``rounds`` rounds.

    ``nbatch`` maps each robot to its batch size. Rounds interleave the robots, as in
    :func:`thread_speedups`.

    Raises:
        ValueError: an unknown robot, or sizes below 1.
        RuntimeError: a worker process failed (its exit code is named).
    """
    for robot, n in nbatch.items():
        get_spec(robot)  # a bad name fails here, not in the workers
        if n < 1:
            raise ValueError(f"nbatch[{robot!r}] = {n!r}; must be >= 1")
    if rounds < 1:
        raise ValueError(f"rounds = {rounds!r}; must be >= 1")
    processes = processes or os.cpu_count() or 1
    ctx = mp.get_context("spawn")  # no fork of a process that may hold rollout threads
    barrier, results = ctx.Barrier(processes), ctx.Queue()
    workers = [ctx.Process(target=_ceiling_worker,
                           args=(rank, dict(nbatch), rounds, barrier, results))
               for rank in range(processes)]
    for w in workers:
        w.start()
    got: dict[int, tuple[dict[str, list[float]], dict[str, list[float]]]] = {}
    try:
        while len(got) < processes:
            try:
                rank, alone, together = results.get(timeout=1.0)
                got[rank] = (alone, together)
            except queue.Empty:
                failed = [w.exitcode for w in workers if w.exitcode not in (None, 0)]
                if failed:
                    raise RuntimeError(f"ceiling worker processes exited with codes "
                                       f"{failed}") from None
    finally:
        for w in workers:
            w.join(timeout=10)
            if w.is_alive():
                w.terminate()
    out = {}
    for robot in nbatch:
        alone = np.asarray(got[0][0][robot])
        together = np.max([got[r][1][robot] for r in range(processes)], axis=0)
        out[robot] = float(np.median(processes * alone / together))
    return out
