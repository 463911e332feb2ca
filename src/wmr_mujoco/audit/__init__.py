"""Bring your own robot: ``wmr audit SCENE.xml`` / :func:`audit` on any MJCF wheeled robot.

The audit finds the wheels and their kinds, derives the ideal kinematic model from the
compiled geometry, drives the manoeuvres the robot's class allows, measures how far MuJoCo
is from the ideal model, and names known modelling pitfalls, each confirmed by a
counterfactual run. See docs/audit.md.

Importing this package does not import MuJoCo (``wmr``'s parser registers the commands
before a rendering command picks its OpenGL backend): :func:`audit` and :class:`Audit`
load :mod:`wmr_mujoco.audit.core` on first use.
"""

from __future__ import annotations

import importlib
import sys
import types
from typing import Any

from wmr_mujoco.audit.errors import AuditInputError, NotWheeledError

__all__ = ["Audit", "AuditInputError", "NotWheeledError", "audit"]


def __getattr__(name: str) -> Any:
    if name in ("audit", "Audit"):
        return getattr(importlib.import_module("wmr_mujoco.audit.core"), name)
    raise AttributeError(f"module 'wmr_mujoco.audit' has no attribute {name!r}")


class _CallableModule(types.ModuleType):
    """``wmr_mujoco.audit`` is this package once imported.

    Calling it runs :func:`~wmr_mujoco.audit.core.audit`, so that
    ``wmr_mujoco.audit(path)`` works before and after the import.
    """

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        return importlib.import_module("wmr_mujoco.audit.core").audit(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
