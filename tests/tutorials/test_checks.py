"""The exercise checks: right answers pass, wrong ones get a hint naming what differs,
malformed ones a hint too, never an exception.

References here are computed by hand from the lecture's formulas with the registry's
default geometry (TricycleParams, OmniParams), not by the checks' own code.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from wmr_mujoco.analytic.wheel_dynamics import WheelDynamics
from wmr_mujoco.robots.omni3.params import OmniParams
from wmr_mujoco.robots.tricycle.params import TricycleParams
from wmr_mujoco.tutorials import checks
from wmr_mujoco.tutorials.checks import CheckResult

MALFORMED = [None, "1.2", [1.0, 2.0], float("nan"), True]


def lecture_J(L: float) -> np.ndarray:
    return np.array([[0.0, 1.0, L], [-math.sqrt(3) / 2, -0.5, L], [math.sqrt(3) / 2, -0.5, L]])


def assert_hint(result: CheckResult, *words: str) -> None:
    assert isinstance(result, CheckResult)
    assert not result.passed and not bool(result)
    assert str(result).startswith("NOT YET")
    for word in words:
        assert word in result.message, result.message


# -- circle radius ---------------------------------------------------------------------

def test_circle_radius() -> None:
    assert checks.check_circle_radius(1.25, 0.5, 0.4).passed        # v/ω by hand
    assert checks.check_circle_radius(1.26, 0.5, 0.4).passed        # 0.8 %: within 1 %
    assert_hint(checks.check_circle_radius(1.3, 0.5, 0.4), "too large")
    assert_hint(checks.check_circle_radius(2.5, 0.5, 0.4), "too large", "ratio 2")
    assert_hint(checks.check_circle_radius(-1.25, 0.5, 0.4), "wrong sign")


@pytest.mark.parametrize("bad", MALFORMED)
def test_circle_radius_malformed(bad: object) -> None:
    assert_hint(checks.check_circle_radius(bad, 0.5, 0.4), "radius")


def test_circle_radius_without_a_circle() -> None:
    assert_hint(checks.check_circle_radius(1.0, 0.5, 0.0), "straight line")
    assert_hint(checks.check_circle_radius(1.0, 0.0, 0.4), "on the spot")


def test_an_unforeseen_answer_still_gets_no_traceback() -> None:
    class Broken:
        @property
        def pose(self):
            raise RuntimeError("no pose here")
    assert_hint(checks.check_closed_loop(Broken()), "could not be checked", "RuntimeError")


# -- closed loop -----------------------------------------------------------------------

def polyline(points: list[tuple[float, float, float]], n: int = 50) -> np.ndarray:
    """Poses along straight segments between the given (x, y, heading) points."""
    out = [np.linspace(a, b, n, endpoint=False) for a, b in itertools.pairwise(points)]
    return np.vstack([*out, [points[-1]]])


def test_closed_loop_triangle_with_turn_passes() -> None:
    h = math.sqrt(3) / 2
    tri = polyline([(0, 0, 0), (1, 0, 0), (1, 0, 2.094), (0.5, h, 2.094), (0.5, h, 4.189),
                    (0, 0, 4.189)])
    result = checks.check_closed_loop(tri)
    assert result.passed, result.message
    assert "-120.0°" in result.message                      # 4.189 rad = 240° ≡ −120°


def test_closed_loop_hints() -> None:
    assert_hint(checks.check_closed_loop(polyline([(0, 0, 0), (1, 0, 0)])), "does not close")
    assert_hint(checks.check_closed_loop(polyline([(0, 0, 0), (0.1, 0, 0), (0, 0, 1)])),
                "travelled only")
    # A full lap of a circle closes with the heading back where it was (mod 360°).
    t = np.linspace(0, 2 * np.pi, 400)
    lap = np.column_stack([np.sin(t), 1 - np.cos(t), t])
    assert_hint(checks.check_closed_loop(lap), "heading changed by only")


@pytest.mark.parametrize("bad", [None, "loop", np.zeros((5, 2)), np.zeros((1, 3))])
def test_closed_loop_malformed(bad: object) -> None:
    assert_hint(checks.check_closed_loop(bad), "trajectory")


# -- parallel parking ------------------------------------------------------------------

def test_parallel_park() -> None:
    start = [1.0, 2.0, math.pi / 2, 0.0]
    # Facing +y, 0.4 m to its left is −x in the world.
    parked = np.array([start, [0.6, 2.05, math.pi / 2 + 0.01, 0.0]])
    assert checks.check_parallel_park(parked).passed
    right = np.array([start, [1.4, 2.0, math.pi / 2, 0.0]])
    assert_hint(checks.check_parallel_park(right), "sideways -0.4")
    skewed = np.array([start, [0.6, 2.3, math.pi / 2 + 0.2, 0.3]])
    assert_hint(checks.check_parallel_park(skewed), "forward offset 0.3", "heading 11.5",
                "steering 0.3")
    assert_hint(checks.check_parallel_park(np.zeros((3, 3))), "shape (N, 4)")
    assert_hint(checks.check_parallel_park(np.zeros((0, 4))), "fewer than two")


# -- tricycle ICR ----------------------------------------------------------------------

def test_tricycle_icr() -> None:
    ell = TricycleParams().wheelbase
    assert checks.check_tricycle_icr(ell / math.tan(0.4), 0.4).passed
    assert_hint(checks.check_tricycle_icr(1.05 * ell / math.tan(0.4), 0.4), "too large")
    assert_hint(checks.check_tricycle_icr(-ell / math.tan(0.4), 0.4), "wrong sign")
    assert_hint(checks.check_tricycle_icr(1.0, 0.0), "steer the front wheel")
    assert_hint(checks.check_tricycle_icr("far", 0.4), "radius should be a number")


# -- omni wheel rates ------------------------------------------------------------------

def test_omni_wheel_rates() -> None:
    p = OmniParams()
    twist = np.array([0.1, -0.05, 0.7])
    rates = lecture_J(p.wheel_distance) @ twist / p.wheel_radius
    assert checks.check_omni_wheel_rates(rates, twist).passed
    assert_hint(checks.check_omni_wheel_rates(-rates, twist), "wrong sign")
    assert_hint(checks.check_omni_wheel_rates(rates * p.wheel_radius, twist), "ground speeds")
    swapped = rates[[0, 2, 1]]
    assert_hint(checks.check_omni_wheel_rates(swapped, twist), "wheel 2", "wheel 3")
    assert "wheel 1" not in checks.check_omni_wheel_rates(swapped, twist).message
    assert_hint(checks.check_omni_wheel_rates([1, 2], twist), "shape (3)")


# -- traction limit --------------------------------------------------------------------

def test_traction_limit() -> None:
    m, J, R, mu = 2.0, 0.02, 0.1, 0.8
    wheel = WheelDynamics(mass=m, inertia=J, radius=R, friction=mu)
    N = m * 9.81
    limit = mu * N * (J + m * R**2) / (m * R)                       # lecture §5, by hand
    assert checks.check_traction_limit(limit, wheel).passed
    assert_hint(checks.check_traction_limit(mu * N * R, wheel), "without inertia")
    assert_hint(checks.check_traction_limit(1.1 * limit, wheel), "too large")
    assert_hint(checks.check_traction_limit("4 N·m", wheel), "should be a number")
    assert_hint(checks.check_traction_limit(limit, "disc"), "WheelDynamics")


# -- omni equations of motion ----------------------------------------------------------

def lecture_eom(include_wheels_in_mass: bool = True, wheel_in_rotation_term: bool = False):
    dyn = checks.omni_dynamics()
    M, Iz, Iw = dyn.mass, dyn.yaw_inertia, dyn.wheel_inertia
    r, L = float(dyn.layout.radii[0]), float(np.hypot(*dyn.layout.positions[0]))
    H = lecture_J(L) / r
    mass = np.diag([M, M, Iz]) + (Iw * H.T @ H if include_wheels_in_mass else 0.0)
    m_rot = M + (Iw * (H.T @ H)[0, 0] if wheel_in_rotation_term else 0.0)

    def f(nu, tau):
        c = nu[2] * np.array([-m_rot * nu[1], m_rot * nu[0], 0.0])
        return np.linalg.solve(mass, H.T @ tau - c)
    return f


def test_omni_equations() -> None:
    assert checks.check_omni_equations(lecture_eom()).passed
    assert_hint(checks.check_omni_equations(lecture_eom(include_wheels_in_mass=False)),
                "with r = 0", "mass matrix")
    # The naive substitution puts wheel inertia into the ψ̇ term: caught with τ = 0.
    assert_hint(checks.check_omni_equations(lecture_eom(wheel_in_rotation_term=True)),
                "with τ = 0", "wheel inertia does not enter it")


def test_omni_equations_malformed() -> None:
    assert_hint(checks.check_omni_equations(None), "give a function")

    def raises(nu, tau):
        raise ZeroDivisionError("oops")
    assert_hint(checks.check_omni_equations(raises), "ZeroDivisionError", "oops")
    assert_hint(checks.check_omni_equations(lambda nu, tau: [0.0, 0.0]), "shape (3)")
    assert_hint(checks.check_omni_equations(lambda nu: nu), "TypeError")
