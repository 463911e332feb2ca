"""Shared test helpers."""

from __future__ import annotations

# isort: off
# wmr_mujoco chooses the OpenGL backend (wmr_mujoco.gl_env) before MuJoCo reads MUJOCO_GL.
import wmr_mujoco  # noqa: F401
import mujoco
# isort: on
import numpy as np
import pytest

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
