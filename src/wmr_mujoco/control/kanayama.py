"""The public names of :mod:`wmr_mujoco.loop.control.kanayama`, importable from here.

The controllers and paths live below the registry (:mod:`wmr_mujoco.loop`), so that
validation scenarios close loops with them.
"""

from wmr_mujoco.loop.control.kanayama import (
    Kanayama,
)

__all__ = [
    "Kanayama"
]
