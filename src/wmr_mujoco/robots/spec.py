""":class:`RobotSpec` and its parts, defined in :mod:`wmr_mujoco.validation.spec`.

The registry's entries are built from these; the type lives in the validation layer so
that generic code can receive a spec without importing the registry. The registry's
:class:`RobotSpec` adds the fields that only layers above validation read (the learning
environments' settings, :class:`~wmr_mujoco.robots.learning.Learning`).
"""

from __future__ import annotations

from dataclasses import dataclass

from wmr_mujoco.robots.learning import Learning
from wmr_mujoco.validation.spec import (
    DEFAULT_JUDGES,
    Clip,
    P,
    PeerComparison,
    Picture,
)
from wmr_mujoco.validation.spec import RobotSpec as _ValidationSpec


@dataclass(frozen=True)
class RobotSpec(_ValidationSpec[P]):
    """A registry entry: every field of the validation layer's spec, and one more.

    Attributes:
        learning: how the learning environments (:mod:`wmr_mujoco.envs`) scale their
            tasks to the robot and randomise it (None:
            :data:`~wmr_mujoco.robots.learning.DEFAULT`).
    """

    learning: Learning | None = None


__all__ = ["DEFAULT_JUDGES", "Clip", "Learning", "PeerComparison", "Picture", "RobotSpec"]
