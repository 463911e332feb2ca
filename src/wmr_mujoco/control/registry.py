"""The controllers by name, the Whipple bicycle's LQR among them.

The planar laws are :mod:`wmr_mujoco.loop.control.registry`'s; this adds ``whipple_lean``
(:mod:`wmr_mujoco.robots.whipple.lean`).

The Whipple law is imported when first built: it reads the robot's own model, whose
package loads MuJoCo; building the command line stays free of it.
"""

from __future__ import annotations

from typing import Any

from wmr_mujoco.loop.control.base import CommandKind, Controller
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
    register,
)

__all__ = ["CONTROLLERS", "KINDS", "SPEED", "SUPPORTS", "VIRTUAL_WHEELBASE", "Factory",
           "build", "check_controller", "kind_of", "register"]


def _whipple_lean(kind: CommandKind, params: Any, speed: float) -> Controller:
    from wmr_mujoco.robots.whipple.lean import WhippleLean

    return WhippleLean(speed=speed, params=params)


register("whipple_lean", _whipple_lean, (CommandKind.WHIPPLE,))
