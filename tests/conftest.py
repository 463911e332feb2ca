"""Shared test helpers."""

from __future__ import annotations

import os

# Offscreen rendering in tests goes through EGL; MuJoCo reads this when first imported.
os.environ.setdefault("MUJOCO_GL", "egl")

import mujoco
import numpy as np
import pytest

#: Robots whose scenes have actuators.
ACTUATED = ("disc", "bicycle", "tricycle", "omni3")


def model_differences(a: mujoco.MjModel, b: mujoco.MjModel, rtol: float = 1e-10) -> list[str]:
    """Names of the MjModel array fields in which ``a`` and ``b`` differ."""
    diffs = []
    for name in dir(a):
        if name.startswith("_"):
            continue
        va = getattr(a, name)
        if not isinstance(va, np.ndarray):
            continue
        vb = getattr(b, name)
        if va.shape != vb.shape:
            diffs.append(f"{name}: shape {va.shape} != {vb.shape}")
        elif va.dtype.kind in "fc":
            if not np.allclose(va, vb, rtol=rtol, atol=1e-12, equal_nan=True):
                diffs.append(name)
        elif not np.array_equal(va, vb):
            diffs.append(name)
    return diffs


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(12345)
