""":class:`RobotSpec` and its parts, defined in :mod:`wmr_mujoco.validation.spec`.

The registry's entries are built from these; the type lives in the validation layer so
that generic code can receive a spec without importing the registry.
"""

from wmr_mujoco.validation.spec import (
    DEFAULT_JUDGES,
    Clip,
    PeerComparison,
    Picture,
    RobotSpec,
)

__all__ = ["DEFAULT_JUDGES", "Clip", "PeerComparison", "Picture", "RobotSpec"]
