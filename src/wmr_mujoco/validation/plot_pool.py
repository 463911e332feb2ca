"""The report's plots drawn in worker processes while the scenarios still run.

A figure takes a fraction of a second of matplotlib (pure Python, so threads would
not help), and ``wmr validate`` draws one per scenario. :class:`PlotPool` hands each
finished scenario's trace to a pool of ``os.cpu_count()`` processes, so drawing overlaps
with the simulation and measurement of the next scenarios in the main process.

The workers are forked from a ``forkserver`` that has imported matplotlib once (never
from the main process, whose MuJoCo rollout threads may be running). They draw into a
hidden staging folder inside the report folder; :func:`~wmr_mujoco.validation.report.
write_report` renames each finished file into place. Leaving the ``with`` block any way
(error, Ctrl-C, SIGTERM) waits for the figures being drawn, cancels the others and
removes the staging folder, and the report folder too if the pool created it, so an
interrupted run leaves nothing behind. Each figure is written atomically
(:func:`wmr_mujoco.atomic.atomic_path`).
"""

from __future__ import annotations

import multiprocessing
import os
import shutil
import tempfile
from collections.abc import Mapping
from concurrent.futures import Future, ProcessPoolExecutor
from pathlib import Path
from types import TracebackType
from typing import TYPE_CHECKING

from wmr_mujoco.validation.plots import plot_trace

if TYPE_CHECKING:
    from wmr_mujoco.validation.runner import ScenarioResult

#: Imported once by the forkserver, so that each worker starts ready to draw.
PRELOAD = ("matplotlib", "matplotlib.pyplot", "wmr_mujoco.validation.metrics",
           "wmr_mujoco.validation.plots")


class PlotPool:
    """Draw scenario plots in worker processes; use as a context manager.

    Args:
        folder: the report folder (created if missing; removed again on exit if it is
            still empty).
        workers: processes (default ``os.cpu_count()``).
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
        self._futures: dict[str, Future[Path | None]] = {}

    def __enter__(self) -> PlotPool:
        if not self.folder.is_dir():
            self.folder.mkdir()
            self._created_folder = True
        self._staging = Path(tempfile.mkdtemp(prefix=".plots-", dir=self.folder))
        context = multiprocessing.get_context("forkserver")
        context.set_forkserver_preload(list(PRELOAD))
        self._pool = ProcessPoolExecutor(self.workers, mp_context=context)
        return self

    def submit(self, result: ScenarioResult) -> None:
        """Start drawing ``result``'s figure (a later result of the same scenario wins)."""
        if self._pool is None or self._staging is None:
            raise RuntimeError("PlotPool.submit outside its `with` block")
        key = result.scenario.key
        path = self._staging / f"{len(self._futures)}.png"
        self._futures[key] = self._pool.submit(plot_trace, result.trace, key, path)

    def collect(self) -> Mapping[str, Path | None]:
        """Wait for every figure: its staged file by scenario key (None: nothing to plot).

        Raises:
            Exception: whatever drawing a figure raised.
        """
        return {key: future.result() for key, future in self._futures.items()}

    def __exit__(self, kind: type[BaseException] | None, err: BaseException | None,
                 tb: TracebackType | None) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
        if self._staging is not None:
            shutil.rmtree(self._staging, ignore_errors=True)
        if self._created_folder and not any(self.folder.iterdir()):
            self.folder.rmdir()

