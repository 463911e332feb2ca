"""What the steered robots' parameters share: their checks and the fields they leave out.

(2,1) :class:`~wmr_mujoco.robots.single_steer.params.SingleSteerParams` and (1,2)
:class:`~wmr_mujoco.robots.double_steer.params.DoubleSteerParams`: frozen dataclasses of
centred steerable wheels on forks, ball casters and a chassis plate; each keeps its own
fields and values and states its layout's bounds, checked here.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Protocol

from wmr_mujoco.models.params.fields import _check_positive_fields, _check_range
from wmr_mujoco.models.params.parts import PAIRS_SET_IMPRATIO, WheelParams
from wmr_mujoco.models.params.wheeled import (
    BallCasterParams,
    _check_caster_fits,
    _check_chassis_size,
)

#: Fields a steered robot's model does not use (its wheel-floor pairs set ``impratio``):
#: ``wmr info`` leaves them out.
UNUSED: tuple[str, ...] = (*PAIRS_SET_IMPRATIO,)


class SteeredParts(Protocol):
    """What :func:`check` reads of a steered robot's parameters besides its layout."""

    @property
    def wheel(self) -> WheelParams:
        """Each steered driven wheel."""

    @property
    def caster(self) -> BallCasterParams:
        """Each ball caster."""

    @property
    def chassis_size(self) -> tuple[float, float, float]:
        """Plate edge lengths (x, y, z), m."""


def check(params: SteeredParts,
          layout: Callable[[SteeredParts], Sequence[tuple[str, float, float]]]) -> None:
    """Check a steered robot's parameters, the first bad value named.

    In order: every field's type and every number positive (masses have no upper bound);
    each layout field ``(name, low, high)`` of ``layout(params)`` in ``(low, high]`` (a
    function: its bounds read fields whose types are checked first); the caster radius below
    the wheel radius; each ``chassis_size`` edge in (0,
    :data:`~wmr_mujoco.models.params.wheeled.MAX_CHASSIS_EDGE`] m.

    Raises:
        ValueError: a field of the wrong type or a value outside its range; the message
            names the field and the valid range.
    """
    _check_positive_fields(params)
    for name, low, high in layout(params):
        _check_range(params, name, low, high)
    _check_caster_fits(params, params.wheel, params.caster)
    _check_chassis_size(params)
