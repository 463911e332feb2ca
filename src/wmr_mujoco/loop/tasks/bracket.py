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

:func:`run_cycle` drives a stepped robot through the cycle; :func:`relative_error`
compares its net displacement with the exact result (``|Δq − Δq_exact| / |Δq_exact|`` of
the planar displacement), :func:`bracket_error` the bracket's prediction with it.
:mod:`wmr_mujoco.control.lie_bracket` sweeps ``ε`` by robot name;
:mod:`wmr_mujoco.loop.tasks.families` judges it over seeded draws.
"""

from __future__ import annotations

import math

import numpy as np

from wmr_mujoco.analytic import nonholonomy
from wmr_mujoco.loop.control.base import CommandKind, clip, positive
from wmr_mujoco.loop.control.registry import kind_of
from wmr_mujoco.loop.robot import Robot

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


def _roll(robot: Robot, d: float, speed: float):
    start = np.array(robot.state.pose, float)
    c, s = math.cos(start[2]), math.sin(start[2])
    for _ in range(round((abs(d) / speed + SEGMENT_EXTRA) / robot.control_period)):
        p = robot.state.pose
        moved = c * (p[0] - start[0]) + s * (p[1] - start[1])
        robot.step([float(clip(GAIN * (d - moved), -speed, speed)), 0.0])


def _turn(robot: Robot, turn: float, rate: float):
    start = float(robot.state.pose[2])
    for _ in range(round((abs(turn) / rate + SEGMENT_EXTRA) / robot.control_period)):
        done = float(robot.state.pose[2]) - start
        robot.step([0.0, float(clip(GAIN * (turn - done), -rate, rate))])


def run_cycle(robot: Robot, eps: float, speed: float = SPEED, rate: float = RATE,
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


def relative_error(net: np.ndarray, d: float, turn: float) -> float:
    """``|Δq − Δq_exact| / |Δq_exact|`` of the planar displacement."""
    ref = exact(d, turn)[:2]
    return float(np.linalg.norm(net[:2] - ref) / np.linalg.norm(ref))


def bracket_error(d: float, turn: float) -> float:
    """``|d Δ [g₁, g₂] − Δq_exact| / |Δq_exact|``: the second-order prediction's error."""
    ref = exact(d, turn)[:2]
    return float(np.linalg.norm(second_order(d, turn)[:2] - ref) / np.linalg.norm(ref))
