"""The controllers by name, built for one robot from its command space and parameters.

A robot's command kind is read from its command channel names (``robot.command_space``,
carried by its registry entry), never from its name: ``(v, omega)`` is a unicycle,
``(v, steer)`` a car, ``(u, v, r)`` a holonomic base, ``(rear_torque, steer_torque)``
the Whipple bicycle. A car's wheelbase is its parameters' ``wheelbase``.

The planar laws are here; a law that reads one robot's own model (the Whipple bicycle's
LQR, :mod:`wmr_mujoco.robots.whipple.lean`) lives with that robot and is added by name
with :func:`register` (:mod:`wmr_mujoco.control.registry` adds ``whipple_lean``).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from wmr_mujoco.loop.control.base import CommandKind, Controller
from wmr_mujoco.loop.control.go_to_pose import GoToPose
from wmr_mujoco.loop.control.holonomic import HolonomicPose
from wmr_mujoco.loop.control.kanayama import Kanayama
from wmr_mujoco.loop.control.pure_pursuit import PurePursuit
from wmr_mujoco.loop.control.stanley import Stanley
from wmr_mujoco.models.params import RobotParams

#: Command channel names -> the command kind.
KINDS: dict[tuple[str, ...], CommandKind] = {
    ("v", "omega"): CommandKind.UNICYCLE,
    ("v", "steer"): CommandKind.CAR,
    ("u", "v", "r"): CommandKind.HOLONOMIC,
    ("rear_torque", "steer_torque"): CommandKind.WHIPPLE,
}
#: Stanley's virtual wheelbase on a unicycle, m.
VIRTUAL_WHEELBASE = 0.3
#: Path speed of the path followers and trackers, m/s.
SPEED = 0.5


def kind_of(names: tuple[str, ...]) -> CommandKind:
    """The command kind of a robot's command channels.

    Raises:
        ValueError: channels of no known kind (the message lists the known ones).
    """
    if tuple(names) not in KINDS:
        raise ValueError(f"command channels {tuple(names)} are of no known kind; known: "
                         f"{', '.join(f'{n} ({k.value})' for n, k in KINDS.items())}")
    return KINDS[tuple(names)]


def _wheelbase(params: RobotParams | Any) -> float:
    ell = getattr(params, "wheelbase", None)
    if ell is None:
        raise ValueError(f"{type(params).__name__} has no wheelbase: not a car")
    return float(ell)


Factory = Callable[[CommandKind, Any, float], Controller]

#: Name -> ``factory(kind, params, speed)``.
CONTROLLERS: dict[str, Factory] = {
    "go_to_pose": lambda kind, p, v: GoToPose(max_speed=v),
    "pure_pursuit": lambda kind, p, v: PurePursuit(
        speed=v, wheelbase=_wheelbase(p) if kind is CommandKind.CAR else None),
    "stanley": lambda kind, p, v: Stanley(
        speed=v, kind=kind,
        wheelbase=_wheelbase(p) if kind is CommandKind.CAR else VIRTUAL_WHEELBASE),
    "kanayama": lambda kind, p, v: Kanayama(
        wheelbase=_wheelbase(p) if kind is CommandKind.CAR else None),
    "holonomic": lambda kind, p, v: HolonomicPose(),
}
#: The kinds each controller can drive.
SUPPORTS: dict[str, tuple[CommandKind, ...]] = {
    "go_to_pose": GoToPose.kinds, "pure_pursuit": PurePursuit.kinds, "stanley": Stanley.kinds,
    "kanayama": Kanayama.kinds, "holonomic": HolonomicPose.kinds,
}


def register(name: str, factory: Factory, kinds: tuple[CommandKind, ...]) -> None:
    """Add a controller by name (again: replaced), building for the command ``kinds``."""
    CONTROLLERS[name] = factory
    SUPPORTS[name] = tuple(kinds)


def check_controller(name: str) -> str:
    """``name`` if it is a controller's name.

    Raises:
        ValueError: unknown name; the message lists the valid ones.
    """
    if name not in CONTROLLERS:
        raise ValueError(f"unknown controller {name!r}; valid controllers: "
                         f"{', '.join(CONTROLLERS)}")
    return name


def build(name: str, command_names: tuple[str, ...], params: Any,
          speed: float = SPEED) -> Controller:
    """The controller ``name`` for a robot with these command channels and parameters.

    Raises:
        ValueError: unknown controller, or one that cannot drive this kind of robot
            (the message names the kinds it drives).
    """
    kind = kind_of(command_names)
    if kind not in SUPPORTS[check_controller(name)]:
        raise ValueError(f"controller {name!r} drives {[k.value for k in SUPPORTS[name]]} "
                         f"robots, not a {kind.value} robot (commands {command_names})")
    return CONTROLLERS[name](kind, params, speed)
