"""Seeded piecewise-constant random inputs: what a policy or controller sends.

A controller holds its command for one control period ``T`` and then steps to the next.
:func:`random_steps` draws such a sequence: each period's input is uniform, component by
component, in ``[−bound_j, bound_j]``, independent of the last, so every period boundary
is a step of random size and direction (the hardest schedule a rate-limited user gives).
:func:`step_draws` draws single steps from rest with the same law.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

#: Control period of the random stepped inputs, s (a 10 Hz policy).
CONTROL_PERIOD = 0.1
#: Longest schedule, s: bounds the memory of a run a user asks for.
MAX_DURATION = 600.0


def _bounds(bounds: Sequence[float]) -> np.ndarray:
    b = np.asarray(bounds, float)
    if b.ndim != 1 or b.size == 0 or not np.all(np.isfinite(b)) or np.any(b < 0):
        raise ValueError(f"bounds = {bounds!r}; need one finite non-negative number per input")
    return b


def random_steps(bounds: Sequence[float], duration: float, seed: int,
                 period: float = CONTROL_PERIOD) -> np.ndarray:
    """Inputs of each control period: (ceil(duration / period), len(bounds)).

    Args:
        bounds: per input component, the largest magnitude.
        duration: seconds, in (0, :data:`MAX_DURATION`].
        seed: seed of ``numpy.random.default_rng``.
        period: control period, s, in (0, duration].

    Raises:
        ValueError: bounds not finite and non-negative, or a duration/period out of range.
    """
    b = _bounds(bounds)
    if not (math.isfinite(duration) and 0 < duration <= MAX_DURATION):
        raise ValueError(f"duration = {duration!r} s; valid range is (0, {MAX_DURATION:g}] s")
    if not (math.isfinite(period) and 0 < period <= duration):
        raise ValueError(f"period = {period!r} s; valid range is (0, duration = {duration:g}] s")
    rng = np.random.default_rng(seed)
    n = math.ceil(duration / period - 1e-9)
    return rng.uniform(-1.0, 1.0, size=(n, b.size)) * b


def step_draws(bounds: Sequence[float], count: int, seed: int) -> np.ndarray:
    """``count`` step commands from rest: (count, len(bounds)), each direction uniform.

    Each draw is a random direction on the box's surface scaled to it: uniform in the box,
    then divided by its largest ``|u_j| / bound_j``, so every step is as large as the range
    allows in its direction (the step whose start-up slides the wheels most).

    Raises:
        ValueError: bounds not finite and non-negative, or ``count`` not in [1, 10000].
    """
    b = _bounds(bounds)
    if not (isinstance(count, int) and 1 <= count <= 10_000):
        raise ValueError(f"count = {count!r}; valid: an integer in [1, 10000]")
    rng = np.random.default_rng(seed)
    u = rng.uniform(-1.0, 1.0, size=(count, b.size))
    scale = np.max(np.abs(u), axis=1, keepdims=True)
    return u / np.where(scale > 0, scale, 1.0) * b
