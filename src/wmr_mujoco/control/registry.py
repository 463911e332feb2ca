"""The public names of :mod:`wmr_mujoco.loop.control.registry`, importable from here.

The controllers and paths live below the registry (:mod:`wmr_mujoco.loop`), so that
validation scenarios close loops with them.
"""

from wmr_mujoco.loop.control.registry import (
    CONTROLLERS,
    KINDS,
    SPEED,
    SUPPORTS,
    VIRTUAL_WHEELBASE,
    Factory,
    build,
    check_controller,
    kind_of,
)

__all__ = [
    "CONTROLLERS", "KINDS", "SPEED", "SUPPORTS", "VIRTUAL_WHEELBASE", "Factory", "build",
    "check_controller", "kind_of"
]
