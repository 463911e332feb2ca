"""Keeping a balancing robot upright after a push, in the physics and on its linear model.

A robot that cannot stand still (the Whipple bicycle) says in its command map how it is
pushed and kept upright (:class:`~wmr_mujoco.validation.command.Balance`, its own data):
its pushed start (steady upright rolling at ``v``, then a lean rate ``φ̇₀``; the Whipple
bicycle's is the stability study's, :func:`wmr_mujoco.robots.whipple.rolling.pushed`),
written into the stepped robot's MuJoCo state after its reset; then, for
:data:`DURATION` seconds, every control period of the law:

* controlled: the robot's balancing law at ``v`` (the Whipple bicycle's LQR steer torque
  and rear-torque speed hold, :mod:`wmr_mujoco.robots.whipple.lean`);
* uncontrolled: its command zero (both torques: the stability study's free run).

It has fallen when ``|φ|`` passes the robot's fall threshold (the Whipple study's
1.2 rad); the upright time is the time of that passage, or the whole run. The model's
run is the robot's linear model under the same law (``Balance.linear``).
"""

from __future__ import annotations

from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np

from wmr_mujoco.loop.build import build_robot
from wmr_mujoco.loop.control.base import positive
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.validation.command import Balance
from wmr_mujoco.validation.spec import RobotSpec

#: Run length, s (issue 25: upright for 10 s after the push).
DURATION = 10.0
#: Largest speed and push accepted, m/s and rad/s.
MAX_SPEED, MAX_PUSH = 30.0, 5.0


@dataclass(frozen=True)
class Upright:
    """One run after a push.

    Attributes:
        backend: ``"mujoco"`` or ``"linear"``.
        speed: m/s.
        push: lean rate given, rad/s.
        controlled: whether the law was on.
        time: ``(K + 1,)`` s.
        lean: ``(K + 1,)`` rad.
        fallen: the fall threshold, rad.
    """

    backend: str
    speed: float
    push: float
    controlled: bool
    time: np.ndarray
    lean: np.ndarray
    fallen: float

    @property
    def upright_time(self) -> float:
        """Time ``|φ|`` first passes the fall threshold, else the run's length, s."""
        over = np.flatnonzero(np.abs(self.lean) > self.fallen)
        return float(self.time[over[0]] if len(over) else self.time[-1])

    @property
    def peak_lean(self) -> float:
        """``max |φ|`` over the run (past the threshold: the run stopped there), rad."""
        return float(np.abs(self.lean).max())


def balance_of(spec: RobotSpec) -> Balance:
    """The robot's :class:`Balance`.

    Raises:
        ValueError: it has none (it stands by itself), or no extras to read the lean from.
    """
    cmap = spec.command
    if cmap is None or cmap.balance is None or cmap.extras is None:
        raise ValueError(f"robot {spec.name!r} has no balancing data (Balance) in its "
                         "command map")
    return cmap.balance


def _check(speed: float, push: float, duration: float) -> None:
    positive("duration", duration)
    if not 0.0 < positive("speed", speed) <= MAX_SPEED:
        raise ValueError(f"speed = {speed!r} m/s; valid range is (0, {MAX_SPEED:g}]")
    if not 0.0 < abs(push) <= MAX_PUSH:
        raise ValueError(f"push = {push!r} rad/s; valid range is (0, {MAX_PUSH:g}] in size")


def physics(spec: RobotSpec, speed: float, push: float | None = None, controlled: bool = True,
            params: RobotParams | None = None, duration: float = DURATION,
            period: float | None = None) -> Upright:
    """The robot in MuJoCo from its pushed start (module docstring); stops once fallen.

    ``push`` None: the robot's nominal push; ``period`` None: its law's period.

    Raises:
        ValueError: a robot without balancing data, or bad speed, push or duration.
        SimulationDivergedError: the physics diverged.
    """
    bal = balance_of(spec)
    push = bal.push if push is None else push
    period = bal.period if period is None else period
    _check(speed, push, duration)
    robot = build_robot(spec, backend="mujoco", control_period=period, params=params)
    law = bal.law(speed, params)
    robot.reset()
    bal.pushed(robot.model, robot.data, params, speed, push)
    extras = spec.command.extras(robot.model, robot.data)
    state = SimpleNamespace(pose=np.zeros(3), twist=np.array([speed, 0.0, 0.0]), extra=extras)
    times, leans = [0.0], [extras[bal.lean]]
    zero = np.zeros(robot.command_space.shape)
    for k in range(round(duration / period)):
        state = robot.step(law(state, None, k * period) if controlled else zero)
        times.append((k + 1) * period)
        leans.append(state.extra[bal.lean])
        if abs(leans[-1]) > bal.fallen:
            break
    return Upright("mujoco", speed, push, controlled, np.array(times), np.array(leans),
                   bal.fallen)


def linear(spec: RobotSpec, speed: float, push: float | None = None, controlled: bool = True,
           params: RobotParams | None = None, duration: float = DURATION,
           period: float | None = None) -> Upright | None:
    """The robot's linear model under the same law (module docstring); None: it has none.

    Raises:
        ValueError: as :func:`physics`.
    """
    bal = balance_of(spec)
    push = bal.push if push is None else push
    period = bal.period if period is None else period
    _check(speed, push, duration)
    if bal.linear is None:
        return None
    leans = np.asarray(bal.linear(speed, push, controlled, params, duration, period), float)
    return Upright("linear", speed, push, controlled, np.arange(len(leans)) * period, leans,
                   bal.fallen)
