"""wmr-mujoco: wheeled mobile robots in MuJoCo, beside their textbook models.

The usual start: ``wmr.simulate(robot, inputs, duration)`` (MuJoCo),
``wmr.predict(...)`` (the analytic model), ``wmr.compare(...)`` (both, judged), ``wmr.load``
(the compiled model); the analytic models are in :mod:`wmr_mujoco.analytic`.

Importing the package does not import MuJoCo: the public names below load lazily, so
that :mod:`wmr_mujoco.render.gl_backend` can still choose the OpenGL backend (EGL, else
OSMesa) before MuJoCo reads ``MUJOCO_GL``.
"""

from __future__ import annotations

import importlib
import os
from typing import Any

#: ``MUJOCO_GL`` as the user set it before importing this package (None if unset).
USER_MUJOCO_GL: str | None = os.environ.get("MUJOCO_GL")
# Offscreen rendering goes through EGL unless the user chose otherwise.
os.environ.setdefault("MUJOCO_GL", "egl")

__version__ = "0.1.0"

_LAZY = {
    "ROBOTS": "wmr_mujoco.robots",
    "RobotSpec": "wmr_mujoco.robots",
    "get_spec": "wmr_mujoco.robots",
    "load": "wmr_mujoco.models.loading",
    "build_scene": "wmr_mujoco.models.loading",
    "ActuationMode": "wmr_mujoco.models.actuation",
    "set_actuation_mode": "wmr_mujoco.models.actuation",
    "ScenarioKind": "wmr_mujoco.validation.scenarios",
    "Scenario": "wmr_mujoco.validation.scenarios",
    "simulate": "wmr_mujoco.api",
    "predict": "wmr_mujoco.api",
    "compare": "wmr_mujoco.api",
    "Trajectory": "wmr_mujoco.api",
    "Comparison": "wmr_mujoco.api",
    "base_pose": "wmr_mujoco.validation.adapters",
    "body_pose": "wmr_mujoco.validation.adapters",
    "body_twist": "wmr_mujoco.validation.adapters",
    "const": "wmr_mujoco.validation.signals",
    "Piecewise": "wmr_mujoco.validation.signals",
    "Sine": "wmr_mujoco.validation.signals",
    "SimulationDivergedError": "wmr_mujoco.sim.stepping",
    **dict.fromkeys(("make", "RobotState", "CommandSpace"), "wmr_mujoco.drive"),
}

__all__ = sorted(_LAZY)


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'wmr_mujoco' has no attribute {name!r}")
