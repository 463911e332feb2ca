"""The public names of :mod:`wmr_mujoco.loop.control.holonomic`, importable from here.

The controllers and paths live below the registry (:mod:`wmr_mujoco.loop`), so that
validation scenarios close loops with them.
"""

from wmr_mujoco.loop.control.holonomic import (
    HolonomicPose,
)

__all__ = [
    "HolonomicPose"
]
