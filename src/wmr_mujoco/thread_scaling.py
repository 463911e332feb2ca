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
from collections.abc import Callable
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


def paired_ratio(slow: Callable[[], None], fast: Callable[[], None], repeats: int,
                 warmup: bool = True) -> tuple[float, float, float]:
    """Median times of ``slow`` and ``fast``, and the median of their per-pair ratios.

    The two run alternately (after one warm-up each unless ``warmup`` is False), which
    cancels the machine's slow drifts in load.
    """
    if repeats < 1:
        raise ValueError(f"repeats = {repeats!r}; must be >= 1")
    if warmup:
        slow()
        fast()
    ts, tf, ratios = [], [], []
    for _ in range(repeats):
        t0 = time.perf_counter()
        slow()
        t1 = time.perf_counter()
        fast()
        t2 = time.perf_counter()
        ts.append(t1 - t0)
        tf.append(t2 - t1)
        ratios.append((t1 - t0) / (t2 - t1))
    return float(np.median(ts)), float(np.median(tf)), float(np.median(ratios))


def thread_speedup(robot: str, repeats: int, threads: int | None = None,
                   target_s: float = TARGET_S) -> dict[str, float]:
    """Rollout steps/s on one thread and on ``threads`` (all cores), and the speedup."""
    threads = threads or os.cpu_count() or 1
    batch = sized_batch(robot, threads, target_s)
    t1, tn, speedup = paired_ratio(batch.runner(1), batch.runner(threads), repeats)
    dt = batch.model.opt.timestep
    return {"nbatch": batch.controls.shape[0], "threads": threads,
            "rollout1_steps_per_s": batch.steps / t1, "rollout1_rtf": batch.steps * dt / t1,
            "rolloutN_steps_per_s": batch.steps / tn, "rollout_speedup": speedup}


def _ceiling_worker(rank: int, robot: str, nbatch: int, repeats: int,
                    barrier: mp.synchronize.Barrier, results: mp.Queue) -> None:
    run = make_batch(robot, nbatch).runner(1)
    run()
    alone, together = [], []
    for _ in range(repeats):
        barrier.wait()
        if rank == 0:
            t0 = time.perf_counter()
            run()
            alone.append(time.perf_counter() - t0)
        barrier.wait()
        t0 = time.perf_counter()
        run()
        together.append(time.perf_counter() - t0)
    results.put((rank, alone, together))


def process_ceiling(robot: str, nbatch: int, repeats: int, processes: int | None = None
                    ) -> float:
    """Median of ``N t_alone / max(t_together)`` over ``repeats`` alternating rounds.

    Raises:
        RuntimeError: a worker process failed (its exit code is named).
    """
    get_spec(robot)  # a bad name fails here, not in the workers
    if nbatch < 1 or repeats < 1:
        raise ValueError(f"nbatch = {nbatch!r}, repeats = {repeats!r}; both must be >= 1")
    processes = processes or os.cpu_count() or 1
    ctx = mp.get_context("spawn")  # no fork of a process that may hold rollout threads
    barrier, results = ctx.Barrier(processes), ctx.Queue()
    workers = [ctx.Process(target=_ceiling_worker,
                           args=(rank, robot, nbatch, repeats, barrier, results))
               for rank in range(processes)]
    for w in workers:
        w.start()
    got: dict[int, tuple[list[float], list[float]]] = {}
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
    alone = np.asarray(got[0][0])
    together = np.max([got[r][1] for r in range(processes)], axis=0)
    return float(np.median(processes * alone / together))
