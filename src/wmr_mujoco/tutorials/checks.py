"""The tutorials' exercise checks: a wrong answer gets a hint, never a traceback.

Each ``check_*`` function takes the student's answer and returns a :class:`CheckResult`:
``passed`` and one message that names what differs (which quantity, by how much, in which
direction) without giving the answer away. Malformed answers (a string, a wrong shape, a
function that raises) are reported the same way. References come from the analytic models
and the robots' registry defaults, never from numbers typed here; each tolerance is stated
beside its check with the reason.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from wmr_mujoco.analytic.planar import path_length, wrap_angle
from wmr_mujoco.analytic.wheel_dynamics import WheelDynamics
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok
from wmr_mujoco.robots.roller_wheels.omni_dynamics import OmniDynamics
from wmr_mujoco.robots.tricycle import analytic as tricycle
from wmr_mujoco.robots.tricycle.params import TricycleParams


@dataclass(frozen=True, repr=False)
class CheckResult:
    """Outcome of one exercise check.

    Attributes:
        exercise: the exercise's name.
        passed: the answer is right within the stated tolerance.
        message: what was measured, or a hint naming what differs.
    """

    exercise: str
    passed: bool
    message: str

    def __bool__(self) -> bool:
        return self.passed

    def __repr__(self) -> str:
        return f"{'PASS' if self.passed else 'NOT YET'} [{self.exercise}] {self.message}"

    __str__ = __repr__


class _HintError(Exception):
    """A wrong or malformed answer; its message is the hint."""


def _exercise(name: str) -> Callable[[Callable[..., str]], Callable[..., CheckResult]]:
    """Wrap a check body: its return value is the success message, a ``_HintError`` the hint."""
    def wrap(body: Callable[..., str]) -> Callable[..., CheckResult]:
        @functools.wraps(body)
        def check(*args: object, **kwargs: object) -> CheckResult:
            try:
                return CheckResult(name, True, body(*args, **kwargs))
            except _HintError as hint:
                return CheckResult(name, False, str(hint))
            except Exception as exc:  # an answer no hint foresaw: still no traceback
                return CheckResult(name, False, f"this answer could not be checked "
                                                f"({type(exc).__name__}: {exc})")
        return check
    return wrap


def _number(name: str, value: object) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.number)):
        raise _HintError(f"{name} should be a number, got {type(value).__name__} {value!r}")
    if not math.isfinite(float(value)):
        raise _HintError(f"{name} should be a finite number, got {value!r}")
    return float(value)


def _array(name: str, value: object, shape: tuple[int | None, ...]) -> np.ndarray:
    try:
        arr = np.asarray(getattr(value, "pose", value), dtype=float)
    except (TypeError, ValueError) as exc:
        raise _HintError(f"{name} should be numbers, got {type(value).__name__} ({exc})") from None
    if arr.ndim != len(shape) or any(s is not None and s != n for s, n in
                                     zip(shape, arr.shape, strict=False)):
        want = "(" + ", ".join("N" if s is None else str(s) for s in shape) + ")"
        raise _HintError(f"{name} should have shape {want}, got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise _HintError(f"{name} contains NaN or infinite values")
    return arr


def _relative(name: str, given: float, expected: float, tol: float, unit: str) -> str:
    """Compare within a relative tolerance; the hint says which way and how far off."""
    err = (given - expected) / abs(expected)
    if abs(err) <= tol:
        return f"{name} = {given:.4g} {unit}, within {100 * tol:g} % of the model"
    if given != 0 and np.sign(given) != np.sign(expected):
        raise _HintError(f"{name} has the wrong sign: {given:.4g} {unit}; check the sign "
                    "convention (counter-clockwise and left are positive)")
    ratio = given / expected
    raise _HintError(f"{name} = {given:.4g} {unit} is {100 * abs(err):.3g} % too "
                f"{'large' if err > 0 else 'small'} (ratio {ratio:.3g}); allowed "
                f"{100 * tol:g} %")


# -- 01 single wheel -------------------------------------------------------------------

@_exercise("circle radius")
def check_circle_radius(radius: object, v: float, omega: float) -> str:
    """The radius of the circle a disc drives at constant ``v`` and ``ω``: ``|v/ω|``.

    Tolerance 1 %: the physics' rolling radius is below R by the contact's penetration
    (about 0.1 %, ``docs/rolling-disc.md``), and a radius fitted to a simulated path
    carries that error.
    """
    r = _number("radius", radius)
    v, omega = _number("v", v), _number("omega", omega)
    if v == 0 or omega == 0:
        raise _HintError(f"v = {v:g} m/s, ω = {omega:g} rad/s: a circle needs both non-zero "
                         "(ω = 0 drives a straight line, v = 0 turns on the spot)")
    expected = abs(v / omega)
    return _relative("radius", r, expected, 0.01, "m")


# -- 02 non-holonomic constraint -------------------------------------------------------

#: A loop must travel at least this far (m), or pivoting on the spot would count.
LOOP_MIN_PATH = 0.5
#: The loop closes if its end lies within 2 % of its path of its start (m/m): the
#: physics follows the model to 0.1-0.4 % of path in the validation, so 2 % leaves room
#: for a loop of segments with sharp corners.
LOOP_CLOSURE = 0.02
#: The heading must change by more than 5°: well above the physics' heading error
#: (0.2° worst in the disc's validation scenarios).
LOOP_MIN_TURN_DEG = 5.0


@_exercise("closed loop")
def check_closed_loop(trajectory: object) -> str:
    """A closed loop in ``(x, y)`` that leaves the heading changed.

    Args:
        trajectory: a :class:`~wmr_mujoco.api.Trajectory` of the disc, or an ``(N, 3)``
            array of ``(x, y, heading)``.
    """
    pose = _array("trajectory", trajectory, (None, 3))
    if len(pose) < 2:
        raise _HintError("the trajectory has fewer than two samples")
    travelled = path_length(pose[:, :2])
    if travelled < LOOP_MIN_PATH:
        raise _HintError(f"the disc travelled only {travelled:.3g} m; drive a loop of at least "
                    f"{LOOP_MIN_PATH} m (turning on the spot is not a loop in (x, y))")
    gap = float(np.hypot(*(pose[-1, :2] - pose[0, :2])))
    if gap > LOOP_CLOSURE * travelled:
        raise _HintError(f"the loop does not close: it ends {gap:.3g} m from its start "
                    f"(allowed {LOOP_CLOSURE * travelled:.3g} m, 2 % of the "
                    f"{travelled:.3g} m travelled)")
    turn = math.degrees(wrap_angle(pose[-1, 2] - pose[0, 2]))
    if abs(turn) < LOOP_MIN_TURN_DEG:
        raise _HintError(f"back at the start, and the heading changed by only {turn:.3g}° "
                    f"(mod 360°); find a loop that leaves it turned by more than "
                    f"{LOOP_MIN_TURN_DEG:g}°")
    return (f"back within {1000 * gap:.3g} mm of the start after {travelled:.3g} m, heading "
            f"turned by {turn:.1f}°: no f(x, y, φ) = 0 can hold")


# -- 03 bicycle ------------------------------------------------------------------------

#: Parallel parking: the goal, in the start frame (m, m, °, rad).
PARK_SIDEWAYS = 0.3
PARK_FORWARD = 0.1
PARK_HEADING_DEG = 3.0
PARK_STEER = 0.05


@_exercise("parallel parking")
def check_parallel_park(trajectory: object) -> str:
    """The bicycle ends at least 0.3 m to the left of its start, parallel to it.

    Targets, in the start frame: sideways ≥ 0.3 m (about a third of a wheelbase, a
    visible park), forward offset within 0.1 m, heading within 3° and steering within
    0.05 rad of the start: several times the physics' errors on a few metres of path
    (0.1-0.2 % of path and 0.5° in the bicycle's validation).

    Args:
        trajectory: the bicycle's :class:`~wmr_mujoco.api.Trajectory` (or an ``(N, 4)``
            array of ``(x, y, heading, steer)``).
    """
    states = _array("trajectory", getattr(trajectory, "states", trajectory), (None, 4))
    if len(states) < 2:
        raise _HintError("the trajectory has fewer than two samples")
    start, end = states[0], states[-1]
    c, s = math.cos(start[2]), math.sin(start[2])
    dx, dy = end[:2] - start[:2]
    forward, sideways = c * dx + s * dy, -s * dx + c * dy
    turn = math.degrees(wrap_angle(end[2] - start[2]))
    problems = []
    if sideways < PARK_SIDEWAYS:
        problems.append(f"sideways {sideways:.3g} m (want ≥ {PARK_SIDEWAYS} m to the left)")
    if abs(forward) > PARK_FORWARD:
        problems.append(f"forward offset {forward:.3g} m (want within ±{PARK_FORWARD} m)")
    if abs(turn) > PARK_HEADING_DEG:
        problems.append(f"heading {turn:.3g}° (want within ±{PARK_HEADING_DEG:g}°)")
    if abs(end[3]) > PARK_STEER:
        problems.append(f"steering {end[3]:.3g} rad (want within ±{PARK_STEER} rad)")
    if problems:
        raise _HintError("not parked yet: " + "; ".join(problems))
    return (f"parked {sideways:.3f} m to the left, {forward:+.3f} m ahead, heading "
            f"{turn:+.2f}°")


# -- 04 tricycle -----------------------------------------------------------------------

@_exercise("tricycle ICR")
def check_tricycle_icr(radius: object, steer: object) -> str:
    """The ICR's distance from the rear-axle midpoint: ``ℓ / tan φ`` (tricycle defaults).

    Tolerance 2 %: the free wheel's rate, from which the radius is found, follows the
    ICR prediction to about 0.1 % in the validation; the servo's steering angle settles
    to 1e-3 rad; 2 % leaves room for rates read at one instant.
    """
    r = _number("radius", radius)
    phi = _number("steer", steer)
    if abs(phi) < 1e-3:
        raise _HintError(f"steer = {phi:.3g} rad: steer the front wheel (|φ| > 0.001 rad) so that "
                    "the ICR is at a finite distance")
    p = TricycleParams()
    return _relative("ICR radius", r, tricycle.icr_radius(phi, p.wheelbase), 0.02, "m")


# -- 05 omni robot ---------------------------------------------------------------------

def omni_layout() -> ok.WheelLayout:
    """The lecture's three-wheel layout with omni3's default radius r and lever L."""
    p = OmniParams()
    return ok.symmetric_layout(p.wheel_radius, p.wheel_distance)


@_exercise("omni wheel rates")
def check_omni_wheel_rates(rates: object, twist: object) -> str:
    """Wheel rates ``θ̇ = (1/r) J ν`` for a body twist ``ν = (u, v, r)`` (omni3's r, L).

    Tolerance 1e-6 rad/s: the same arithmetic, only rounding may differ.
    """
    nu = _array("twist", twist, (3,))
    got = _array("rates", rates, (3,))
    expected = ok.wheel_rates(omni_layout(), nu)
    diff = got - expected
    bad = [i for i in range(3) if abs(diff[i]) > 1e-6]
    if not bad:
        return f"θ̇ = ({', '.join(f'{x:.4g}' for x in got)}) rad/s"
    if np.allclose(got, -expected, atol=1e-6):
        raise _HintError("every rate has the wrong sign: θ̇ > 0 drives a wheel along its "
                    "drive direction, counter-clockwise round the platform")
    if np.allclose(got, expected * OmniParams().wheel_radius, atol=1e-6):
        raise _HintError("these are the wheels' ground speeds r θ̇ in m/s: θ̇ = (1/r) J ν, in rad/s")
    names = ", ".join(f"wheel {i + 1} ({got[i]:.4g} rad/s) is too "
                      f"{'small' if diff[i] < 0 else 'large'}" for i in bad)
    raise _HintError(f"these differ: {names}; row i of J is (−sin α_i, cos α_i, L) with "
                "α = 0°, 120°, 240°")


# -- 06 wheel dynamics -----------------------------------------------------------------

@_exercise("traction limit")
def check_traction_limit(torque: object, wheel: WheelDynamics) -> str:
    """The largest axle torque that still rolls: ``μ N (J + m R²) / (m R)``.

    Tolerance 1 %: the same formula from the same constants; 1 % allows constants
    rounded to three digits.
    """
    if not isinstance(wheel, WheelDynamics):
        raise _HintError(f"wheel should be a WheelDynamics, got {type(wheel).__name__}")
    tau = _number("torque", torque)
    expected = wheel.max_rolling_torque
    if abs(tau - wheel.friction * wheel.normal * wheel.radius) <= 0.01 * expected:
        raise _HintError("μ N R is the limit of a wheel without inertia or mass of its own "
                    "(J = 0); the torque also spins the wheel up: use F_T = m ẍ and "
                    "ẍ = τR/(J + mR²)")
    return _relative("traction limit", tau, expected, 0.01, "N·m")


# -- 07 Lagrange equations -------------------------------------------------------------

@functools.lru_cache(maxsize=1)
def omni_dynamics() -> OmniDynamics:
    """omni3's reduced Lagrange model, with M, I_z and I_w read from the compiled model."""
    from wmr_mujoco.robots.omni3.runs import hybrid  # the registry (loads the model)
    from wmr_mujoco.robots.roller_wheels.model_info import lagrange_of

    return lagrange_of(hybrid())


#: Body twists and torques the equations of motion are tried at (seeded, fixed).
_STATES = np.random.default_rng(29).uniform(-1.0, 1.0, size=(6, 6)) * [0.5, 0.5, 2, .3, .3, .3]


@_exercise("omni equations of motion")
def check_omni_equations(acceleration: object) -> str:
    """``ν̇ = f(ν, τ)`` from the lecture's equations against the reduced Lagrange model.

    Tried at six seeded states: first with ``r = 0`` (mass matrix and input map), then
    with ``τ = 0`` (the ψ̇ term alone), then at the states as drawn. Tolerance 1e-6
    relative to the largest acceleration: the same linear algebra, only rounding differs.

    Args:
        acceleration: a function ``f(nu, tau) -> nu_dot`` of the body twist
            ``(u, v, r)`` and the wheel torques ``(τ₁, τ₂, τ₃)``.
    """
    if not callable(acceleration):
        raise _HintError(f"give a function f(nu, tau) returning nu_dot, got "
                    f"{type(acceleration).__name__}")
    dyn = omni_dynamics()
    stages = (("with r = 0 (no rotation)", [1, 1, 0], [1, 1, 1],
               "check the mass matrix diag(M, M, I_z) + I_w HᵀH and the input Hᵀτ"),
              ("with τ = 0 and the platform turning", [1, 1, 1], [0, 0, 0],
               "check the ψ̇ (r) term: r (−M v, M u, 0), and that wheel inertia does not "
               "enter it"),
              ("at general states", [1, 1, 1], [1, 1, 1], "check every term"))
    for label, nu_mask, tau_mask, advice in stages:
        for state in _STATES:
            nu, tau = state[:3] * nu_mask, state[3:] * tau_mask
            try:
                got = _array("f(nu, tau)", acceleration(nu.copy(), tau.copy()), (3,))
            except _HintError:
                raise
            except Exception as exc:
                raise _HintError(f"your function raised {type(exc).__name__}: {exc}") from None
            expected = dyn.body_acceleration(nu, tau)
            scale = max(float(np.max(np.abs(expected))), 1e-9)
            if np.max(np.abs(got - expected)) > 1e-6 * scale:
                comp = ["u̇", "v̇", "ṙ"][int(np.argmax(np.abs(got - expected)))]
                raise _HintError(f"{label}, {comp} differs (at ν = {np.round(nu, 3)}, τ = "
                            f"{np.round(tau, 3)}): {advice}")
    return "the lecture's equations, reduced, match the Lagrange–d'Alembert model"
