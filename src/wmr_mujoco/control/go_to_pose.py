"""The public names of :mod:`wmr_mujoco.loop.control.go_to_pose`, importable from here.

The controllers and paths live below the registry (:mod:`wmr_mujoco.loop`), so that
validation scenarios close loops with them.
"""

from wmr_mujoco.loop.control.go_to_pose import (
    GoToPose,
)

__all__ = [
    "GoToPose"
]
