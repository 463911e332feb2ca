"""Bring your own robot: ``wmr audit SCENE.xml`` / :func:`audit` on any MJCF wheeled robot.

The audit finds the wheels and their kinds, derives the ideal kinematic model from the
compiled geometry, drives the manoeuvres the robot's class allows, measures how far MuJoCo
is from the ideal model, and names known modelling pitfalls, each confirmed by a
counterfactual run. See docs/audit.md.
"""

from __future__ import annotations

from wmr_mujoco.audit.core import Audit, audit
from wmr_mujoco.audit.errors import AuditInputError, NotWheeledError

__all__ = ["Audit", "AuditInputError", "NotWheeledError", "audit"]


class _CallableModule(__import__("types").ModuleType):
    """``wmr_mujoco.audit`` is this package once imported.

    Calling it runs :func:`audit`, so that ``wmr_mujoco.audit(path)`` works before and after the
    import.
    """

    def __call__(self, *args: object, **kwargs: object) -> Audit:
        return audit(*args, **kwargs)


__import__("sys").modules[__name__].__class__ = _CallableModule
