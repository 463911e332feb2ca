"""The public names of :mod:`wmr_mujoco.robots.whipple.lean`, importable from here.

The law reads the Whipple bicycle's own model, so it lives in the robot's folder; its
registry entry hands it to the balancing scenarios (``Balance.law``).
"""

from wmr_mujoco.robots.whipple.lean import (
    STATE_KEYS,
    BrysonWeights,
    WhippleLean,
    input_matrix,
    lqr_gain,
)

__all__ = [
    "STATE_KEYS", "BrysonWeights", "WhippleLean", "input_matrix", "lqr_gain"
]
