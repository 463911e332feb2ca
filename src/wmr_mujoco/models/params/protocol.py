"""What generic code uses of any robot's parameters, and the defaults rule."""

from __future__ import annotations

from typing import Any, ClassVar, Protocol, TypeVar

from wmr_mujoco.models.params.parts import SimParams


class RobotParams(Protocol):
    """What generic code uses of a robot's parameter dataclass.

    Every robot's parameters are a frozen dataclass (so ``dataclasses.fields`` and
    ``dataclasses.replace`` work on them) with simulation settings and a total mass.
    """

    __dataclass_fields__: ClassVar[dict[str, Any]]

    @property
    def sim(self) -> SimParams:
        """Simulation settings."""
        ...

    @property
    def total_mass(self) -> float:
        """Mass of everything that moves, kg."""
        ...


ParamsT = TypeVar("ParamsT")


def params_or_default(params: object, params_type: type[ParamsT]) -> ParamsT:
    """``params`` checked against ``params_type``, or its defaults if None.

    Raises:
        ValueError: ``params`` is of another type; the message names both.
    """
    if params is None:
        return params_type()
    if not isinstance(params, params_type):
        raise ValueError(f"params must be a {params_type.__name__}, got "
                         f"{type(params).__name__}")
    return params
