"""Choosing the OpenGL backend for offscreen rendering: EGL, else OSMesa.

MuJoCo binds its GL context class from ``MUJOCO_GL`` when it is first imported, and
PyOpenGL fixes its platform once, so a failed EGL start cannot be retried as OSMesa
in the same process. :func:`select_backend` therefore probes each backend in a short
subprocess and sets ``MUJOCO_GL`` before MuJoCo is imported here.
"""

from __future__ import annotations

import os
import subprocess
import sys

import wmr_mujoco
from wmr_mujoco.gl_env import DISABLED

#: Backends tried, in order, when the user has not set ``MUJOCO_GL``.
BACKENDS = ("egl", "osmesa")
INSTALL_HINT = (
    "no offscreen OpenGL backend works on this machine. Install Mesa's EGL "
    "(Debian/Ubuntu: apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri) or OSMesa "
    "(apt-get install libosmesa6), or on a GPU server the NVIDIA driver's EGL; "
    "then rerun, or set MUJOCO_GL explicitly."
)
_PROBE = (
    "import mujoco\n"
    "ctx = mujoco.GLContext(64, 64)\n"
    "ctx.make_current()\n"
    "m = mujoco.MjModel.from_xml_string('<mujoco><worldbody><geom size=\".1\"/>"
    "</worldbody></mujoco>')\n"
    "r = mujoco.Renderer(m, 16, 16)\n"
    "r.update_scene(mujoco.MjData(m))\n"
    "r.render()\n"
)


class RenderingUnavailableError(RuntimeError):
    """No offscreen OpenGL backend could be started."""


def probe(backend: str, timeout: float = 60.0) -> str | None:
    """Try to render one frame with ``backend`` in a subprocess.

    Returns:
        None if it works, else the last line of the error it printed.
    """
    env = dict(os.environ, MUJOCO_GL=backend)
    if backend == "osmesa":
        env["PYOPENGL_PLATFORM"] = "osmesa"
    try:
        proc = subprocess.run([sys.executable, "-c", _PROBE], env=env, capture_output=True,
                              text=True, timeout=timeout, check=False)
    except subprocess.TimeoutExpired:
        return f"timed out after {timeout:g} s"
    if proc.returncode == 0:
        return None
    lines = [ln for ln in proc.stderr.strip().splitlines() if ln.strip()]
    return lines[-1] if lines else f"exit code {proc.returncode}"


def mujoco_imported() -> bool:
    """Whether MuJoCo is imported in this process (then its backend is fixed)."""
    return "mujoco" in sys.modules


def select_backend() -> str:
    """Make sure offscreen rendering can start; return the backend in use.

    If the user set ``MUJOCO_GL``, or MuJoCo is already imported, that backend is used
    as it is. Otherwise EGL is tried, then OSMesa, and ``MUJOCO_GL`` is set to the first
    that renders.

    Raises:
        RenderingUnavailableError: no backend works, or the one the user set cannot load
            (:mod:`wmr_mujoco.gl_env`); the message says what to install.
    """
    choice = wmr_mujoco.GL
    if choice.requested is not None and choice.problem is not None:
        raise RenderingUnavailableError(choice.problem)
    if choice.requested is not None and choice.requested.lower().strip() in DISABLED:
        raise RenderingUnavailableError(f"MUJOCO_GL={choice.requested} turns rendering off; "
                                        "unset it (EGL, else OSMesa, is then chosen)")
    chosen = wmr_mujoco.USER_MUJOCO_GL
    if chosen is None and mujoco_imported():
        chosen = os.environ.get("MUJOCO_GL", "egl")
        if chosen in DISABLED:
            raise RenderingUnavailableError(
                f"{INSTALL_HINT} ({choice.problem or 'MUJOCO_GL=' + chosen})")
    if chosen is not None:
        return chosen
    errors = []
    for backend in BACKENDS:
        err = probe(backend)
        if err is None:
            os.environ["MUJOCO_GL"] = backend
            if backend == "osmesa":
                os.environ["PYOPENGL_PLATFORM"] = "osmesa"
            return backend
        errors.append(f"{backend}: {err}")
    raise RenderingUnavailableError(f"{INSTALL_HINT} ({'; '.join(errors)})")
