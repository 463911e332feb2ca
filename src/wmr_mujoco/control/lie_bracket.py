"""The Lie-bracket parking manoeuvre in the physics: sideways by four allowed motions.

A unicycle-class robot (``(v, ω)`` commands: diffdrive, disc) has the input fields
``g₁ = (cos ψ, sin ψ, 0)`` (roll) and ``g₂ = (0, 0, 1)`` (turn); it cannot move
sideways at any instant. The four-segment cycle (:mod:`wmr_mujoco.analytic.nonholonomy`)

    g₁ for d,   g₂ for Δ,   −g₁ for d,   −g₂ for Δ

(forward ``d`` m, turn ``Δ`` rad, back ``d``, turn back) moves it, in its start frame, by
exactly

    (d (1 − cos Δ), −d sin Δ),   heading unchanged,

and to second order by ``d Δ [g₁, g₂] = d Δ (sin ψ₀, −cos ψ₀, 0)`` (for ``d = Δ = ε``:
``ε² [g₁, g₂]``), a sideways step.

Each segment is one input field alone, its amount closed-loop: a roll commands
``(v, 0)`` with ``v = clip(k (d − s), −v_max, v_max)``, ``s`` the distance moved along the
segment's start heading; a turn commands ``(0, ω)`` with
``ω = clip(k (Δ − (ψ − ψ_s)), −ω_max, ω_max)``; each for :data:`SEGMENT_EXTRA` s beyond
its nominal ``d / v_max`` (``Δ / ω_max``), so that ``k = 4 1/s`` leaves ``e^{-12}`` of it.
Open loop the wheel-rate servos deliver the segments millimetres short (speeding up
lags; at the stop the contacts spring back), which the bracket's sideways step (also
millimetres for small ε) would not survive. The feedback only sets HOW FAR each field
is followed: the sideways motion itself is never commanded (it cannot be).

:func:`measure` runs the cycle on the ``mujoco`` backend (contact physics) and on the
``kinematic`` backend, and compares the net displacements with the exact result and the
bracket's prediction (relative errors ``|Δq − Δq_exact| / |Δq_exact|`` of the planar
displacement). :func:`sweep` does so over ``ε`` and seeded draws of ``(v, ω)``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.analytic import nonholonomy
from wmr_mujoco.control.base import CommandKind, positive
from wmr_mujoco.control.registry import kind_of

#: Time of a segment beyond its nominal length, s; feedback gain, 1/s; control period, s.
SEGMENT_EXTRA, GAIN, PERIOD = 3.0, 4.0, 0.02
#: Default segment speed m/s and turn rate rad/s; ranges of the seeded draws.
SPEED, RATE = 0.25, 0.5
SPEED_RANGE, RATE_RANGE = (0.15, 0.35), (0.3, 0.8)
#: The sweep of ε (d = ε m, Δ = ε rad).
EPSILONS = (0.1, 0.2, 0.3, 0.4, 0.5)
#: Largest ε accepted (a quarter turn).
MAX_EPS = math.pi / 2


def exact(d: float, turn: float) -> np.ndarray:
    """Net ``(Δx, Δy, Δψ)`` of the ideal cycle in the start frame (module docstring)."""
    return np.array([*nonholonomy.unicycle_cycle_displacement(d, turn), 0.0])


def second_order(d: float, turn: float) -> np.ndarray:
    """``d Δ [g₁, g₂](q₀)`` at the start frame's ``q₀ = 0`` (bracket by finite differences)."""
    def g1(q: np.ndarray) -> np.ndarray:
        return np.array([math.cos(q[2]), math.sin(q[2]), 0.0])

    def g2(q: np.ndarray) -> np.ndarray:
        return np.array([0.0, 0.0, 1.0])
    return d * turn * nonholonomy.lie_bracket(g1, g2, np.zeros(3))


def check_eps(eps: float) -> float:
    """``eps`` if in ``(0, π/2]``, else ``ValueError``."""
    if isinstance(eps, bool) or not isinstance(eps, (int, float)) or not 0 < eps <= MAX_EPS:
        raise ValueError(f"eps = {eps!r}; must be a number in (0, {MAX_EPS:.4f}]")
    return float(eps)


def _roll(robot, d: float, speed: float):
    start = np.array(robot.state.pose, float)
    c, s = math.cos(start[2]), math.sin(start[2])
    for _ in range(round((abs(d) / speed + SEGMENT_EXTRA) / robot.control_period)):
        p = robot.state.pose
        moved = c * (p[0] - start[0]) + s * (p[1] - start[1])
        robot.step([float(np.clip(GAIN * (d - moved), -speed, speed)), 0.0])


def _turn(robot, turn: float, rate: float):
    start = float(robot.state.pose[2])
    for _ in range(round((abs(turn) / rate + SEGMENT_EXTRA) / robot.control_period)):
        done = float(robot.state.pose[2]) - start
        robot.step([0.0, float(np.clip(GAIN * (turn - done), -rate, rate))])


def run_cycle(robot, eps: float, speed: float = SPEED, rate: float = RATE,
              start_heading: float = 0.0) -> tuple[np.ndarray, float, float]:
    """Drive a stepped ``(v, ω)`` robot through the cycle from ``(0, 0, start_heading)``.

    Returns:
        ``(Δx, Δy, Δψ)`` in the start frame, and the cycle's ``d = Δ = ε``.

    Raises:
        ValueError: the robot is not driven by ``(v, ω)``, or bad ``eps``, speed, rate.
    """
    if kind_of(robot.command_space.names) is not CommandKind.UNICYCLE:
        raise ValueError(f"the cycle needs (v, omega) commands; robot "
                         f"{robot.spec.name!r} takes {robot.command_space.names}")
    eps = check_eps(eps)
    speed, rate = positive("speed", speed), positive("rate", rate)
    p0 = np.array(robot.reset(pose=(0.0, 0.0, start_heading)).pose, float)
    _roll(robot, eps, speed)
    _turn(robot, eps, rate)
    _roll(robot, -eps, speed)
    _turn(robot, -eps, rate)
    p1 = np.array(robot.state.pose, float)
    c, s = math.cos(p0[2]), math.sin(p0[2])
    dx, dy = p1[0] - p0[0], p1[1] - p0[1]
    return np.array([c * dx + s * dy, -s * dx + c * dy, p1[2] - p0[2]]), eps, eps


@dataclass(frozen=True)
class BracketRow:
    """One ε of the sweep.

    Attributes:
        eps: the nominal ε.
        exact_net: ``|Δq_exact|`` (planar), m.
        bracket_error: ``|ε² [g₁, g₂] − Δq_exact| / |Δq_exact|`` (second order's error).
        model_error: worst relative error of the kinematic backend over the draws.
        physics_worst: worst relative error of the physics over the draws.
        physics_median: its median.
        physics_heading: worst ``|Δψ|`` of the physics, rad.
        draws: number of draws.
    """

    eps: float
    exact_net: float
    bracket_error: float
    model_error: float
    physics_worst: float
    physics_median: float
    physics_heading: float
    draws: int


def draw(k: int) -> tuple[float, float, float]:
    """``(speed, rate, start heading)`` of draw ``k`` (``default_rng(k)``, uniform)."""
    rng = np.random.default_rng(k)
    return (float(rng.uniform(*SPEED_RANGE)), float(rng.uniform(*RATE_RANGE)),
            float(rng.uniform(-math.pi, math.pi)))


def relative_error(net: np.ndarray, d: float, turn: float) -> float:
    """``|Δq − Δq_exact| / |Δq_exact|`` of the planar displacement."""
    ref = exact(d, turn)[:2]
    return float(np.linalg.norm(net[:2] - ref) / np.linalg.norm(ref))


def measure(robot_name: str = "diffdrive", eps: float = 0.3, draws: int = 20,
            params=None) -> BracketRow:
    """The cycle at ``eps`` over ``draws`` seeded ``(v, ω, ψ₀)`` on both backends.

    Raises:
        ValueError: bad ``eps`` or ``draws``, or a robot not driven by ``(v, ω)``.
        SimulationDivergedError: the physics diverged.
    """
    from wmr_mujoco.drive import make

    if isinstance(draws, bool) or not isinstance(draws, int) or not 1 <= draws <= 1000:
        raise ValueError(f"draws = {draws!r}; must be an integer in [1, 1000]")
    check_eps(eps)
    phys = make(robot_name, backend="mujoco", control_period=PERIOD, params=params)
    model = make(robot_name, backend="kinematic", control_period=PERIOD, params=params)
    errs, model_errs, headings = [], [], []
    for k in range(draws):
        speed, rate, psi0 = draw(k)
        net, d, turn = run_cycle(phys, eps, speed, rate, psi0)
        errs.append(relative_error(net, d, turn))
        headings.append(abs(net[2]))
        net_m, d, turn = run_cycle(model, eps, speed, rate, psi0)
        model_errs.append(relative_error(net_m, d, turn))
    d = turn = eps
    ref = exact(d, turn)[:2]
    bracket = float(np.linalg.norm(second_order(d, turn)[:2] - ref) / np.linalg.norm(ref))
    return BracketRow(eps, float(np.linalg.norm(ref)), bracket, float(max(model_errs)),
                      float(max(errs)), float(np.median(errs)), float(max(headings)), draws)


def sweep(robot_name: str = "diffdrive", epsilons: Sequence[float] = EPSILONS,
          draws: int = 20) -> list[BracketRow]:
    """:func:`measure` for each ``ε``."""
    return [measure(robot_name, float(e), draws) for e in epsilons]
