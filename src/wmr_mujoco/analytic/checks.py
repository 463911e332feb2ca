"""Argument checks shared by the analytical modules (clear ``ValueError`` messages)."""

from __future__ import annotations

import math

import numpy as np


def as_array(name: str, value: object, shape: tuple[int | None, ...]) -> np.ndarray:
    """Return ``value`` as a finite float array of ``shape`` (None: any length).

    Raises:
        ValueError: naming ``name``, the expected and the actual shape, or the
            non-finite entries.
    """
    if type(value) is np.ndarray and value.dtype == np.float64 and (
            value.shape == shape or (value.ndim == len(shape) and all(
                s is None or s == n for s, n in zip(shape, value.shape, strict=True)))):
        # Fast path for the arrays the integrators pass around. A small one is summed in
        # Python floats (no numpy call, no floating-point flags): NaN and ±Inf survive a
        # sum, so a finite sum means finite entries; a sum that overflowed is checked
        # entry by entry.
        if not ((value.size <= 16 and math.isfinite(sum(value.ravel().tolist())))
                or np.isfinite(value).all()):
            raise ValueError(f"{name} contains non-finite values: "
                             f"{value[~np.isfinite(value)][:3]}")
        return value
    arr = np.asarray(value, dtype=float)
    ok = arr.ndim == len(shape) and all(s is None or s == n for s, n in zip(shape, arr.shape,
                                                                              strict=False))
    if not ok:
        dims = ["N" if s is None else str(s) for s in shape]
        want = f"({dims[0]},)" if len(dims) == 1 else "(" + ", ".join(dims) + ")"
        raise ValueError(f"{name} must have shape {want}, got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} contains non-finite values: {arr[~np.isfinite(arr)][:3]}")
    return arr


def positive(name: str, value: float) -> float:
    """Return ``value`` if it is a finite number > 0, else raise ``ValueError``."""
    if not isinstance(value, (int, float, np.floating)) or not math.isfinite(value) \
            or value <= 0:
        raise ValueError(f"{name} = {value!r}; must be a finite number > 0")
    return float(value)


def non_negative(name: str, value: float) -> float:
    """Return ``value`` if it is a finite number >= 0, else raise ``ValueError``."""
    if not isinstance(value, (int, float, np.floating)) or not math.isfinite(value) \
            or value < 0:
        raise ValueError(f"{name} = {value!r}; must be a finite number >= 0")
    return float(value)
