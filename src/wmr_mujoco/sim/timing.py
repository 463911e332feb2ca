"""Wall-clock timing: medians of repeated runs, paired ratios, and the stepping loop.

Machines here are shared and noisy, so every figure is a median of repeats, and two
things compared are timed alternately so that load drifts fall on both alike.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import mujoco
import numpy as np


def timed(fn: Callable[[], object]) -> float:
    """Wall time of one call of ``fn``, s."""
    t0 = time.perf_counter()
    fn()
    return time.perf_counter() - t0


def _check_count(name: str, value: int) -> None:
    if value < 1:
        raise ValueError(f"{name} = {value!r}; must be >= 1")


def median_time(fn: Callable[[], object], repeats: int, warmup: bool = True) -> float:
    """Median wall time of ``fn()`` over ``repeats`` runs (after one warm-up if ``warmup``).

    Raises:
        ValueError: ``repeats`` below 1.
    """
    _check_count("repeats", repeats)
    if warmup:
        fn()
    return float(np.median([timed(fn) for _ in range(repeats)]))


def paired_ratio(slow: Callable[[], object], fast: Callable[[], object], rounds: int,
                 warmup: bool = True) -> tuple[float, float, float]:
    """Median times of ``slow`` and ``fast``, and the median of their per-pair ratios.

    The two run alternately (after one warm-up each unless ``warmup`` is False), so the
    machine's drifts in load fall on both alike.

    Raises:
        ValueError: ``rounds`` below 1.
    """
    _check_count("rounds", rounds)
    if warmup:
        slow()
        fast()
    ts, tf = [], []
    for _ in range(rounds):
        ts.append(timed(slow))
        tf.append(timed(fast))
    return float(np.median(ts)), float(np.median(tf)), float(np.median(np.divide(ts, tf)))


def step_loop_time(model: mujoco.MjModel, ctrl: np.ndarray, nstep: int, repeats: int
                   ) -> float:
    """Median wall time of ``nstep`` bare ``mj_step`` calls from rest with ``ctrl`` held, s.

    The real-time factor of the model is ``nstep · Δt / step_loop_time(...)``.
    """
    def loop() -> None:
        data = mujoco.MjData(model)
        data.ctrl[:] = ctrl
        for _ in range(nstep):
            mujoco.mj_step(model, data)
    return median_time(loop, repeats)
