"""The public names of :mod:`wmr_mujoco.loop.control.base`, importable from here.

The controllers and paths live below the registry (:mod:`wmr_mujoco.loop`), so that
validation scenarios close loops with them.
"""

from wmr_mujoco.loop.control.base import (
    CommandKind,
    Controller,
    StateLike,
    Trajectory,
    command_kind,
    positive,
    steer_command,
    wrap,
)

__all__ = [
    "CommandKind", "Controller", "StateLike", "Trajectory", "command_kind", "positive",
    "steer_command", "wrap"
]
