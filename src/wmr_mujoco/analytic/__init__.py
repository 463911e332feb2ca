"""The textbook models: kinematics, non-holonomic constraints and dynamics.

Conventions (all modules): world frame x, y on the floor, z up; angles in radians,
counter-clockwise positive about z; a wheel rate θ̇ > 0 rolls the wheel forward along its
heading. Symbols follow ``docs/analytical.md``.

Every module is reachable from here (``wmr_mujoco.analytic.unicycle.rates``, ...), and the
models' main names are exported directly. Nothing here imports MuJoCo.
"""

import importlib
import pkgutil
from types import ModuleType

from wmr_mujoco.analytic.integrate import integrate, rk4_step
from wmr_mujoco.analytic.planar import path_length, wrap_angle
from wmr_mujoco.analytic.wheel_dynamics import WheelDynamics

#: The analytic modules (one model or tool each), found in this package's folder.
MODULES = tuple(m.name for m in pkgutil.iter_modules(__path__) if not m.name.startswith("_"))

__all__ = [
    "MODULES",
    "WheelDynamics",
    "integrate",
    "path_length",
    "rk4_step",
    "wrap_angle",
    *MODULES,
]


def __getattr__(name: str) -> ModuleType:
    if name in MODULES:
        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
