"""How batched ``mujoco.rollout`` scales from one thread to all cores, against the machine.

A batch of identical open-loop rollouts (the robot cruising on its first validation
scenario's inputs) is timed on one thread and on all cores, alternately, and the speedup
is the median of the per-pair ratios ``t₁ / t_N``. Each batch is sized to take about
``target_s`` seconds on one thread, so thread start-up and scheduling jitter are small
against the work, and its output arrays are allocated once (page faults would otherwise
be timed too).

The machine's own ceiling is measured in the same rounds with processes instead of
threads: ``N`` processes run the single-thread batch at once (started together at a
barrier), and the ceiling is ``N t₁ / max(t_together)``. Threads sharing one process
should do no better than processes sharing nothing, so it is the reference for the
thread speedup; on a virtual machine it is often well below ``N`` (shared caches, memory
bandwidth, clock boost, the hypervisor's other guests). See :func:`scaling`.
"""

from __future__ import annotations

import multiprocessing as mp
import os
import queue
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import mujoco
import numpy as np
from mujoco import rollout

from wmr_mujoco.lookup import load
from wmr_mujoco.robots import get_spec
from wmr_mujoco.sim.timing import timed

#: Steps per rollout in a batch.
NSTEP = 1000
#: Wall time one batch should take on one thread, s.
TARGET_S = 0.4


def driving_controls(model: mujoco.MjModel, robot: str) -> np.ndarray:
    """Steady controls of the robot's first kinematic scenario (its cruising inputs).

    Raises:
        ValueError: the robot has no kinematic scenario; the message lists those that do.
    """
    from wmr_mujoco.robots import ROBOTS
    from wmr_mujoco.validation.runner import make_adapter
    from wmr_mujoco.validation.scenarios import ScenarioKind

    spec = get_spec(robot)
    scenario = next((s for s in spec.scenarios if s.kind is ScenarioKind.KINEMATIC), None)
    if scenario is None:
        valid = [n for n, sp in ROBOTS.items()
                 if any(s.kind is ScenarioKind.KINEMATIC for s in sp.scenarios)]
        raise ValueError(f"robot {robot!r} has no kinematic scenario to drive; valid robots: "
                         f"{', '.join(valid)}")
    adapter = make_adapter(spec, scenario, model)
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


def batch_size(robot: str, threads: int, target_s: float = TARGET_S) -> int:
    """Rollouts in a batch that takes about ``target_s`` on one thread.

    A multiple of ``threads``, at least two per thread.
    """
    probe = make_batch(robot, 2)
    run = probe.runner(1)
    run()
    per_rollout = timed(run) / 2
    return max(2, round(target_s / per_rollout / threads)) * threads


def _scaling_worker(rank: int, nbatch: dict[str, int], rounds: int, nthread: int,
                    barrier: mp.synchronize.Barrier, results: mp.Queue) -> None:
    batches = {robot: make_batch(robot, n) for robot, n in nbatch.items()}
    one = {robot: b.runner(1) for robot, b in batches.items()}
    many = {robot: b.runner(nthread) for robot, b in batches.items()} if rank == 0 else {}
    for fn in [*one.values(), *many.values()]:
        fn()  # warm-up
    times = {robot: {"alone": [], "threads": [], "together": []} for robot in batches}
    for _ in range(rounds):
        for robot in batches:
            barrier.wait()
            if rank == 0:
                times[robot]["alone"].append(timed(one[robot]))
                times[robot]["threads"].append(timed(many[robot]))
            barrier.wait()
            times[robot]["together"].append(timed(one[robot]))
    results.put((rank, times))


def scaling(robots: Sequence[str], rounds: int, workers: int | None = None,
            target_s: float = TARGET_S) -> dict[str, dict[str, float]]:
    """Rollout thread speedup and the machine's process ceiling, measured side by side.

    ``workers`` (default: all cores) fresh processes each build every robot's batch
    (:func:`batch_size`). In every round, for each robot in turn: process 0 runs the batch
    on one thread (``t₁``) and then on ``workers`` threads (``t_N``) while the others wait;
    then all processes run it on one thread at once (``t_k``). Per robot::

        thread speedup = median(t₁ / t_N)
        process ceiling = median(N t₁ / max_k t_k)

    Measuring in fresh processes keeps the harness's own state out of the figures, and
    measuring both in the same rounds lets them share the machine's drifts in load.

    Returns:
        Per robot: ``nbatch``, ``threads``, ``rollout1_steps_per_s``, ``rollout1_rtf``,
        ``rolloutN_steps_per_s``, ``rollout_speedup``, ``process_ceiling``.

    Raises:
        ValueError: an unknown robot, or ``rounds``/``workers`` below 1.
        RuntimeError: a worker process failed (its exit code is named).
    """
    for robot in robots:
        get_spec(robot)  # a bad name fails here, not in the workers
    workers = workers or os.cpu_count() or 1
    if rounds < 1 or workers < 1:
        raise ValueError(f"rounds = {rounds!r}, workers = {workers!r}; both must be >= 1")
    nbatch = {robot: batch_size(robot, workers, target_s) for robot in robots}
    ctx = mp.get_context("spawn")  # no fork of a process that may hold rollout threads
    barrier, results = ctx.Barrier(workers), ctx.Queue()
    procs = [ctx.Process(target=_scaling_worker,
                         args=(rank, nbatch, rounds, workers, barrier, results))
             for rank in range(workers)]
    for p in procs:
        p.start()
    got: dict[int, dict[str, dict[str, list[float]]]] = {}
    try:
        while len(got) < workers:
            try:
                rank, times = results.get(timeout=1.0)
                got[rank] = times
            except queue.Empty:
                failed = [p.exitcode for p in procs if p.exitcode not in (None, 0)]
                if failed:
                    raise RuntimeError(f"scaling worker processes exited with codes "
                                       f"{failed}") from None
    finally:
        for p in procs:
            p.join(timeout=10)
            if p.is_alive():
                p.terminate()
    out = {}
    for robot in robots:
        t1 = np.asarray(got[0][robot]["alone"])
        tn = np.asarray(got[0][robot]["threads"])
        together = np.max([got[r][robot]["together"] for r in range(workers)], axis=0)
        steps = nbatch[robot] * NSTEP
        dt = load(robot).opt.timestep
        out[robot] = {"nbatch": nbatch[robot], "threads": workers,
                      "rollout1_steps_per_s": steps / float(np.median(t1)),
                      "rollout1_rtf": steps * dt / float(np.median(t1)),
                      "rolloutN_steps_per_s": steps / float(np.median(tn)),
                      "rollout_speedup": float(np.median(t1 / tn)),
                      "process_ceiling": float(np.median(workers * t1 / together))}
    return out
