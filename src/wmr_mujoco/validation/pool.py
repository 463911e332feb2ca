"""Worker processes for ``wmr validate``: the scenarios and the report's plots.

Scheduling, measuring and measurement scenarios are Python, and a figure takes a
fraction of a second of matplotlib; all hold the GIL, so threads would not help.
:class:`ValidationPool` spreads them over ``os.cpu_count()`` processes: each unit of
:func:`~wmr_mujoco.validation.runner.work_units` (a rollout batch of kinematic or dynamic
scenarios, or one measurement scenario) runs in a worker through
:func:`~wmr_mujoco.validation.runner.run_all`, the same code as in one process, so the
metrics are the same; the main process takes the units no worker has started yet, and
hands each result's figure to a worker (:func:`~wmr_mujoco.validation.plots.plot_trace`)
as soon as it is back.

The workers are forked from a ``forkserver`` that has imported matplotlib, MuJoCo and the
robots once (never from the main process, whose rollout threads may be running). They
draw into a hidden staging folder inside the report folder;
:func:`~wmr_mujoco.validation.report.write_report` renames each finished file into
place. Leaving the ``with`` block normally waits for the tasks under way; leaving it by
an error, Ctrl-C or SIGTERM ends the workers at once. Either way the staging folder is
removed, and the report folder too if the pool created it and it is empty, so an
interrupted run leaves nothing behind. Each figure is
written atomically (:func:`wmr_mujoco.atomic.atomic_path`).
"""

from __future__ import annotations

import multiprocessing
import os
import shutil
import tempfile
from collections.abc import Mapping, Sequence
from concurrent.futures import Future, ProcessPoolExecutor
from pathlib import Path
from types import TracebackType
from typing import TYPE_CHECKING

from wmr_mujoco.validation.plots import plot_trace

if TYPE_CHECKING:
    from wmr_mujoco.sim.engine import Engine
    from wmr_mujoco.validation.runner import Outcome, ScenarioResult
    from wmr_mujoco.validation.scenarios import Scenario

#: Imported once by the forkserver, so that each worker starts ready.
PRELOAD = ("matplotlib", "matplotlib.pyplot", "wmr_mujoco.validation.plots",
           "wmr_mujoco.validation.runner")


class ValidationPool:
    """Run measurement scenarios and draw plots in worker processes; a context manager.

    Args:
        folder: the report folder (created if missing; removed again on exit if it is
            still empty).
        workers: processes (default ``os.cpu_count()``).

    Raises:
        ValueError: ``workers`` < 1.
    """

    def __init__(self, folder: Path, workers: int | None = None) -> None:
        n = workers if workers is not None else (os.cpu_count() or 1)
        if n < 1:
            raise ValueError(f"workers = {n}; must be >= 1")
        self.folder = Path(folder)
        self.workers = n
        self._created_folder = False
        self._staging: Path | None = None
        self._pool: ProcessPoolExecutor | None = None
        self._plots: dict[str, Future[Path | None]] = {}

    def __enter__(self) -> ValidationPool:
        if not self.folder.is_dir():
            self.folder.mkdir()
            self._created_folder = True
        self._staging = Path(tempfile.mkdtemp(prefix=".plots-", dir=self.folder))
        if "forkserver" in multiprocessing.get_all_start_methods():
            context = multiprocessing.get_context("forkserver")
            context.set_forkserver_preload(list(PRELOAD))
        else:  # Windows: each worker imports for itself
            context = multiprocessing.get_context("spawn")
        self._pool = ProcessPoolExecutor(self.workers, mp_context=context)
        return self

    def _executor(self) -> ProcessPoolExecutor:
        if self._pool is None or self._staging is None:
            raise RuntimeError("ValidationPool used outside its `with` block")
        return self._pool

    def run(self, scenarios: Sequence[Scenario], engine: Engine
            ) -> Future[tuple[list[Outcome], list[str]]] | None:
        """Start registered scenarios in a worker; None if one is not in the registry.

        The worker runs them through :func:`~wmr_mujoco.validation.runner.run_all` (the
        same code as in this process, so the same metrics) and gives back their outcomes
        and progress messages. The scenarios themselves, which may hold closures, stay
        here; the worker finds them by robot and name.
        """
        from wmr_mujoco.robots import ROBOTS

        for scenario in scenarios:
            spec = ROBOTS.get(scenario.robot)
            registered = next((s for s in (spec.scenarios if spec else ())
                               if s.name == scenario.name), None)
            if registered is None or registered != scenario or \
                    registered.evaluate is not scenario.evaluate:
                return None
        return self._executor().submit(_run_registered,
                                       [(s.robot, s.name) for s in scenarios], engine)

    def plot(self, result: ScenarioResult) -> None:
        """Start drawing ``result``'s figure (a later result of the same scenario wins)."""
        key = result.scenario.key
        assert self._staging is not None  # set with the executor
        path = self._staging / f"{len(self._plots)}.png"
        self._plots[key] = self._executor().submit(plot_trace, result.trace, key, path)

    def collect(self) -> Mapping[str, Path | None]:
        """Wait for every figure: its staged file by scenario key (None: nothing to plot).

        Raises:
            Exception: whatever drawing a figure raised.
        """
        return {key: future.result() for key, future in self._plots.items()}

    def __exit__(self, kind: type[BaseException] | None, err: BaseException | None,
                 tb: TracebackType | None) -> None:
        try:
            if self._pool is not None:
                if kind is not None:
                    # Stop now: workers write only into the staging folder, removed
                    # below. (The executor ends its workers publicly only from 3.14.)
                    workers = getattr(self._pool, "_processes", None) or {}
                    for process in list(workers.values()):
                        process.terminate()
                self._pool.shutdown(wait=True, cancel_futures=True)
        finally:
            if self._staging is not None:
                shutil.rmtree(self._staging, ignore_errors=True)
            if self._created_folder and not any(self.folder.iterdir()):
                self.folder.rmdir()


def _run_registered(keys: list[tuple[str, str]], engine: Engine
                    ) -> tuple[list[Outcome], list[str]]:
    """Registered scenarios (robot, name) through the runner, in a worker."""
    from wmr_mujoco.robots import get_spec
    from wmr_mujoco.validation.runner import run_all

    messages: list[str] = []
    results = run_all([get_spec(robot).scenario(name) for robot, name in keys],
                      messages.append, engine)
    # Per-scenario "[i/n]" lines are the caller's to print, with its own numbering.
    return ([(r.rows, r.trace, r.error) for r in results],
            [m for m in messages if not m.startswith("[")])
