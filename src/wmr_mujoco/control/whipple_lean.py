"""The public names of :mod:`wmr_mujoco.loop.control.whipple_lean`, importable from here.

The controllers and paths live below the registry (:mod:`wmr_mujoco.loop`), so that
validation scenarios close loops with them.
"""

from wmr_mujoco.loop.control.whipple_lean import (
    STATE_KEYS,
    BrysonWeights,
    WhippleLean,
    input_matrix,
    lqr_gain,
)

__all__ = [
    "STATE_KEYS", "BrysonWeights", "WhippleLean", "input_matrix", "lqr_gain"
]
