"""Shared test helpers."""

from __future__ import annotations

# isort: off
# wmr_mujoco chooses the OpenGL backend (wmr_mujoco.gl_env) before MuJoCo reads MUJOCO_GL.
import wmr_mujoco  # noqa: F401
import mujoco
# isort: on
from collections.abc import Callable

import numpy as np
import pytest

from wmr_mujoco.robots.roller_wheels import omni_kinematics as ok

#: Robots whose scenes have actuators.
ACTUATED = ("disc", "bicycle", "tricycle", "omni3")


def model_differences(a: mujoco.MjModel, b: mujoco.MjModel, rtol: float = 1e-10) -> list[str]:
    """Names of the MjModel array fields in which ``a`` and ``b`` differ."""
    diffs = []
    for name in dir(a):
        if name.startswith("_"):
            continue
        va = getattr(a, name)
        if not isinstance(va, np.ndarray):
            continue
        vb = getattr(b, name)
        if va.shape != vb.shape:
            diffs.append(f"{name}: shape {va.shape} != {vb.shape}")
        elif va.dtype.kind in "fc":
            if not np.allclose(va, vb, rtol=rtol, atol=1e-12, equal_nan=True):
                diffs.append(name)
        elif not np.array_equal(va, vb):
            diffs.append(name)
    return diffs


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(12345)


def _drawing_problem() -> str | None:
    """Why nothing can be drawn here (None: an offscreen backend renders)."""
    from wmr_mujoco.render.gl_backend import RenderingUnavailableError, select_backend

    try:
        select_backend()
    except RenderingUnavailableError as err:
        return str(err)
    return None


_GL_PROBLEM = pytest.StashKey[str | None]()


def pytest_configure(config):
    """Find out once per process (and per xdist worker) whether anything can be drawn."""
    config.stash[_GL_PROBLEM] = _drawing_problem()


def pytest_report_header(config):
    """One line when the drawing tests are skipped."""
    problem = config.stash.get(_GL_PROBLEM, None)
    if problem:
        return f"drawing tests (marked gl): skipped, no OpenGL backend here ({problem})"
    return None


def pytest_collection_modifyitems(config, items):
    """Skip the tests that draw (marked ``gl``) where no OpenGL backend exists, saying why."""
    problem = config.stash.get(_GL_PROBLEM, None)
    if problem is None:
        return
    skip = pytest.mark.skip(reason=f"no OpenGL backend: {problem}")
    for item in items:
        if item.get_closest_marker("gl"):
            item.add_marker(skip)


# --- Kinematics helpers of the analytic tests (textbook and robot-own models alike) ---

Accel = Callable[[np.ndarray, np.ndarray], np.ndarray]


def _steady_turn_off_circle(accel: Accel, H: np.ndarray, c_term: Callable[[np.ndarray],
                            np.ndarray], mass: float, flip: bool) -> float:
    """Newton–Euler in the world frame: a platform at speed u turning at r moves on a
    circle of radius u/r only if the net force is the centripetal M u r towards the
    centre. Torques τ = H⁻ᵀ c(ν) (c flipped if ``flip``) hold ν̇ = 0 in the model;
    integrate the WORLD path over half a turn and return its distance off that circle, m.

    Also checks that ``c(ν)`` equals the centripetal force derived in the world frame
    (``M u²/ρ`` towards the centre, on the body's left for u, r > 0), sign included.
    """
    nu0 = np.array([0.3, 0.0, 1.0])
    sign = -1.0 if flip else 1.0
    f_world = np.array([0.0, mass * nu0[0] ** 2 / (nu0[0] / nu0[2]), 0.0])
    tau = np.linalg.solve(H.T, sign * c_term(nu0))
    np.testing.assert_allclose(H.T @ tau, sign * f_world, atol=1e-12)
    x = np.array([0.0, 0.0, 0.0, *nu0])
    dt = 5e-3

    def f(s: np.ndarray) -> np.ndarray:
        return np.concatenate([ok.body_to_world(s[2], s[3:]), accel(s[3:], tau)])

    for _ in range(int(np.pi / dt)):  # half a circle
        k1 = f(x)
        k2 = f(x + 0.5 * dt * k1)
        k3 = f(x + 0.5 * dt * k2)
        k4 = f(x + dt * k3)
        x = x + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    radius = nu0[0] / nu0[2]
    return float(abs(np.hypot(x[0], x[1] - radius) - radius))


@pytest.fixture
def steady_turn_off_circle() -> Callable[..., float]:
    """:func:`_steady_turn_off_circle`: the ψ̇ cross-term's sign check of a planar model."""
    return _steady_turn_off_circle


def _point_velocity(q: np.ndarray, qdot: np.ndarray, offset_body: tuple[float, float]
                    ) -> np.ndarray:
    """World velocity of a point fixed at ``offset_body`` in the body frame of heading q[2].

    Rigid-body motion, independent of any module under test: ``v_p = v + ψ̇ ẑ × R(ψ) p``.
    """
    c, s = np.cos(q[2]), np.sin(q[2])
    r = np.array([c * offset_body[0] - s * offset_body[1],
                  s * offset_body[0] + c * offset_body[1]])
    return qdot[:2] + qdot[2] * np.array([-r[1], r[0]])


@pytest.fixture
def point_velocity() -> Callable[[np.ndarray, np.ndarray, tuple[float, float]], np.ndarray]:
    """:func:`_point_velocity`, for the kinematics tests."""
    return _point_velocity


def rk4_path(f: Callable[[np.ndarray], np.ndarray], x0: np.ndarray, dt: float,
             steps: int) -> np.ndarray:
    """Classic RK4 of ``ẋ = f(x)`` (an integrator written here, not the package's)."""
    x = np.asarray(x0, float)
    for _ in range(steps):
        k1 = f(x)
        k2 = f(x + 0.5 * dt * k1)
        k3 = f(x + 0.5 * dt * k2)
        k4 = f(x + dt * k3)
        x = x + dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
    return x


@pytest.fixture
def rk4() -> Callable[..., np.ndarray]:
    """:func:`rk4_path`, for the kinematics tests."""
    return rk4_path


# --- Parameter bounds at their edges (tests/models/test_params.py, tests/robots/*/) ---------

def assert_bound_edge(cls: type, base: dict, field: str, ok: float, bad: float,
                      valid: str) -> None:
    """``cls(field=ok)`` is valid, ``cls(field=bad)`` a ValueError giving the range ``valid``."""
    cls(**base, **{field: ok})
    with pytest.raises(ValueError) as err:
        cls(**base, **{field: bad})
    assert str(err.value) == (f"{cls.__name__}.{field} = {bad!r} is not physical; "
                              f"valid range is {valid}")


def assert_count_edge(cls: type, field: str, ok: int, bad: int, valid: str) -> None:
    """An integer field: ``ok`` valid, ``bad`` a ValueError giving the integer range."""
    cls(**{field: ok})
    with pytest.raises(ValueError) as err:
        cls(**{field: bad})
    assert str(err.value) == f"{cls.__name__}.{field} = {bad}; valid range is integers {valid}"
