"""Keeping the Whipple bicycle upright after a push, in the physics and on the linear model.

The start is the stability study's (:mod:`wmr_mujoco.robots.whipple.stability`): steady
upright rolling at ``v`` (:func:`~wmr_mujoco.robots.whipple.rolling.roll_steadily`), then
a lean rate ``φ̇₀`` about the ground line (:func:`~wmr_mujoco.robots.whipple.rolling.push`),
written into the stepped robot's MuJoCo state after its reset (the stepping API resets
to its keyframe's speed). Then, for :data:`DURATION` seconds, every control period:

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

from wmr_mujoco.control.base import positive
from wmr_mujoco.control.whipple_lean import WhippleLean, input_matrix
from wmr_mujoco.models.params import params_or_default
from wmr_mujoco.robots.whipple import analytic as whipple
from wmr_mujoco.robots.whipple import rolling, stability
from wmr_mujoco.robots.whipple.params import WhippleParams

#: The bicycle has fallen past this lean, rad.
FALLEN = stability.FALLEN
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


def physics(speed: float, push: float = PUSH, controlled: bool = True,
            params: WhippleParams | None = None, duration: float = DURATION,
            period: float = PERIOD) -> Upright:
    """The MuJoCo bicycle (module docstring); stops once fallen.

    Raises:
        ValueError: bad speed, push or duration.
        SimulationDivergedError: the physics diverged.
    """
    from wmr_mujoco.drive import make

    positive("duration", duration)
    rolling.check_speed(speed)
    robot = make("whipple", backend="mujoco", control_period=period, params=params)
    law = WhippleLean(speed, params_or_default(params, WhippleParams))
    robot.reset()
    rolling.roll_steadily(robot.model, robot.data, params, speed)
    rolling.push(robot.model, robot.data, push)
    extras = robot.spec.command.extras(robot.model, robot.data)
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


def draw(k: int) -> tuple[float, float]:
    """``(speed, push)`` of draw ``k``: uniform in the ranges, push sign drawn."""
    rng = np.random.default_rng(k)
    speed = float(rng.uniform(*SPEED_RANGE))
    push = float(rng.choice([-1.0, 1.0]) * rng.uniform(*PUSH_RANGE))
    return speed, push


@dataclass(frozen=True)
class UprightFamily:
    """Controlled runs over seeded draws.

    Attributes:
        draws: number.
        min_upright: shortest upright time, s, ``(physics, linear)``.
        worst_peak: largest peak lean, rad, ``(physics, linear)``.
        median_peak: median peak lean, rad, ``(physics, linear)``.
    """

    draws: int
    min_upright: tuple[float, float]
    worst_peak: tuple[float, float]
    median_peak: tuple[float, float]


def family(draws: int = 20, params: WhippleParams | None = None) -> UprightFamily:
    """Controlled runs (physics and linear model) over ``draws`` seeded draws.

    Raises:
        ValueError: ``draws`` not an integer in [1, 1000].
    """
    if isinstance(draws, bool) or not isinstance(draws, int) or not 1 <= draws <= 1000:
        raise ValueError(f"draws = {draws!r}; must be an integer in [1, 1000]")
    runs = [(physics(*draw(k), params=params), linear(*draw(k), params=params))
            for k in range(draws)]
    up = np.array([[r.upright_time for r in pair] for pair in runs])
    peak = np.array([[r.peak_lean for r in pair] for pair in runs])
    return UprightFamily(draws, tuple(up.min(0)), tuple(peak.max(0)),
                         tuple(np.median(peak, 0)))
