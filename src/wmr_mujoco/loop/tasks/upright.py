"""Keeping the Whipple bicycle upright after a push, in the physics and on the linear model.

The start is the robot's pushed start (its command map's ``pushed``; the Whipple
bicycle's is the stability study's, :func:`wmr_mujoco.robots.whipple.rolling.pushed`):
steady upright rolling at ``v``, then a lean rate ``φ̇₀`` about the ground line, written
into the stepped robot's MuJoCo state after its reset (the stepping API resets to its
keyframe's speed). Then, for :data:`DURATION` seconds, every control period:

* controlled: the LQR steer torque and the rear-torque speed hold of
  :class:`~wmr_mujoco.control.whipple_lean.WhippleLean` designed at ``v``;
* uncontrolled: both torques zero (the stability study's free run).

The bicycle has fallen when ``|φ|`` passes :data:`FALLEN` (the study's 1.2 rad); the
upright time is the time of that passage, or the whole run. The model's run is the
linearised benchmark ``ẋ = A(v) x + B T_δ`` from ``x₀ = (0, 0, φ̇₀, 0)`` with the same law
held over each control period (exact zero-order-hold discretisation,
``[Φ Γ; 0 I] = exp([A B; 0 0] T)``).
"""

from __future__ import annotations

from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np
from scipy.linalg import expm

from wmr_mujoco.analytic import whipple
from wmr_mujoco.loop.build import build_robot
from wmr_mujoco.loop.control.base import positive
from wmr_mujoco.loop.control.whipple_lean import WhippleLean, input_matrix
from wmr_mujoco.models.params import params_or_default
from wmr_mujoco.models.params_whipple import WhippleParams
from wmr_mujoco.validation.spec import RobotSpec

#: The bicycle has fallen past this lean, rad (the stability study's threshold: past it
#: the frame is within 0.37 rad of lying on the floor).
FALLEN = 1.2
#: Largest speed and push accepted, m/s and rad/s (those of the pushed start).
MAX_SPEED, MAX_PUSH = 30.0, 5.0
#: Run length, s; push, rad/s; control period, s (the closed loop's fastest pole,
#: ≈ −43 1/s, moves by λT = 0.09 per period).
DURATION, PUSH, PERIOD = 10.0, 0.5, 0.002
#: Speeds of the headline runs, m/s (below the weave speed: it falls uncontrolled).
SPEEDS = (3.0, 2.0)
#: Family draws: speed range m/s, push magnitude range rad/s (sign drawn too).
SPEED_RANGE, PUSH_RANGE = (2.0, 3.0), (0.25, 0.75)


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
    """

    backend: str
    speed: float
    push: float
    controlled: bool
    time: np.ndarray
    lean: np.ndarray

    @property
    def upright_time(self) -> float:
        """Time ``|φ|`` first passes :data:`FALLEN`, else the run's length, s."""
        over = np.flatnonzero(np.abs(self.lean) > FALLEN)
        return float(self.time[over[0]] if len(over) else self.time[-1])

    @property
    def peak_lean(self) -> float:
        """``max |φ|`` while upright, rad."""
        return float(np.abs(self.lean).max())


def physics(spec: RobotSpec, speed: float, push: float = PUSH, controlled: bool = True,
            params: WhippleParams | None = None, duration: float = DURATION,
            period: float = PERIOD) -> Upright:
    """The robot of ``spec`` in MuJoCo from its pushed start (module docstring).

    The run stops once the bicycle has fallen.

    Raises:
        ValueError: a robot without a pushed start, or bad speed, push or duration.
        SimulationDivergedError: the physics diverged.
    """
    positive("duration", duration)
    if not 0.0 < positive("speed", speed) <= MAX_SPEED:
        raise ValueError(f"speed = {speed!r} m/s; valid range is (0, {MAX_SPEED:g}]")
    if not 0.0 < abs(push) <= MAX_PUSH:
        raise ValueError(f"push = {push!r} rad/s; valid range is (0, {MAX_PUSH:g}] in size")
    cmap = spec.command
    if cmap is None or cmap.pushed is None or cmap.extras is None:
        raise ValueError(f"robot {spec.name!r} has no pushed start in its command map")
    robot = build_robot(spec, backend="mujoco", control_period=period, params=params)
    law = WhippleLean(speed, params_or_default(params, WhippleParams))
    robot.reset()
    cmap.pushed(robot.model, robot.data, params, speed, push)
    extras = cmap.extras(robot.model, robot.data)
    state = SimpleNamespace(pose=np.zeros(3), twist=np.array([speed, 0.0, 0.0]), extra=extras)
    times, leans = [0.0], [extras["lean"]]
    for k in range(round(duration / period)):
        command = law(state, None, k * period) if controlled else np.zeros(2)
        state = robot.step(command)
        times.append((k + 1) * period)
        leans.append(state.extra["lean"])
        if abs(leans[-1]) > FALLEN:
            break
    return Upright("mujoco", speed, push, controlled, np.array(times), np.array(leans))


def linear(speed: float, push: float = PUSH, controlled: bool = True,
           params: WhippleParams | None = None, duration: float = DURATION,
           period: float = PERIOD) -> Upright:
    """The linearised benchmark under the same law (module docstring)."""
    p = params_or_default(params, WhippleParams)
    mats = whipple.matrices(p)
    a, b = whipple.state_matrix(positive("speed", speed), mats), input_matrix(mats)
    big = np.zeros((5, 5))
    big[:4, :4], big[:4, 4:] = a * period, b * period
    e = expm(big)
    phi, gamma = e[:4, :4], e[:4, 4]
    law = WhippleLean(speed, p)
    x = np.array([0.0, 0.0, push, 0.0])
    steps = round(positive("duration", duration) / period)
    leans = [0.0]
    for _ in range(steps):
        x = phi @ x + gamma * (law.torque(x) if controlled else 0.0)
        leans.append(x[0])
        if abs(x[0]) > FALLEN:
            break
    return Upright("linear", speed, push, controlled, np.arange(len(leans)) * period,
                   np.array(leans))
