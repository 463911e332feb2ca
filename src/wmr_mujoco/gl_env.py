"""Which OpenGL backend MuJoCo and dm_control may load, decided before either is imported.

MuJoCo (``mujoco.rendering.classic.gl_context``) and dm_control (``dm_control._render``)
each load the backend named by ``MUJOCO_GL`` when they are first imported, and both fail
at import, not at the first frame, when that backend's library or display is missing:
``MUJOCO_GL=osmesa`` without OSMesa breaks ``import mujoco`` with a PyOpenGL
``AttributeError``, dm_control's EGL backend opens a display at import. A command that
draws nothing (``wmr list``, ``wmr validate``, the API) must not need OpenGL at all, so
:func:`configure` (run once when :mod:`wmr_mujoco` is imported) checks cheaply, by
library look-up only, whether the backend asked for (``MUJOCO_GL``, default EGL, else
OSMesa) can load; if not it sets ``MUJOCO_GL=disable`` for this process, so both libraries
import without a backend, and keeps the reason. Drawing then fails with that reason
(:func:`wmr_mujoco.render.gl_backend.select_backend`, exit code 3), and nothing else does.
"""

from __future__ import annotations

import ctypes.util
import os
from collections.abc import Callable, MutableMapping
from dataclasses import dataclass

#: ``MUJOCO_GL`` values that turn rendering off in MuJoCo and dm_control.
DISABLED = ("disable", "disabled", "off", "false", "0")
#: Values MuJoCo accepts on Linux that open a window system (GLFW or GLX).
WINDOWED = ("glfw", "glx", "enable", "enabled", "on", "true", "1", "")
#: Offscreen backends and the shared library each loads.
OFFSCREEN_LIBRARY = {"egl": "EGL", "osmesa": "OSMesa"}
#: Where :func:`configure` leaves its reason for child processes (test workers, tools),
#: which inherit ``MUJOCO_GL=disable`` and must know why.
PROBLEM_ENV = "WMR_GL_PROBLEM"
#: What to install for each offscreen backend (Debian/Ubuntu).
INSTALL = {"egl": "apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri",
           "osmesa": "apt-get install libosmesa6"}


@dataclass(frozen=True)
class GLChoice:
    """The decision :func:`configure` took.

    Attributes:
        requested: ``MUJOCO_GL`` as the user set it (None: unset).
        backend: the value ``MUJOCO_GL`` now has in this process.
        problem: why the requested (or default) backend cannot load; None when it can.
    """

    requested: str | None
    backend: str
    problem: str | None


def backend_problem(backend: str, environ: MutableMapping[str, str] | None = None,
                    find_library: Callable[[str], str | None] = ctypes.util.find_library,
                    ) -> str | None:
    """Why ``backend`` cannot be loaded here, from library look-ups alone (None: it can).

    Args:
        backend: a ``MUJOCO_GL`` value (case and spaces ignored).
        environ: the environment read for a display (default ``os.environ``).
        find_library: library look-up (``ctypes.util.find_library``; a stub in tests).
    """
    environ = os.environ if environ is None else environ
    name = backend.lower().strip()
    if name in DISABLED:
        return None
    if name in OFFSCREEN_LIBRARY:
        if find_library(OFFSCREEN_LIBRARY[name]) is None:
            return (f"lib{OFFSCREEN_LIBRARY[name]} is not installed "
                    f"(Debian/Ubuntu: {INSTALL[name]})")
        return None
    if name in WINDOWED:
        if not (environ.get("DISPLAY") or environ.get("WAYLAND_DISPLAY")):
            return "it opens a window, and there is no display (DISPLAY is unset)"
        return None
    valid = ", ".join(sorted({*OFFSCREEN_LIBRARY, "glfw", "glx", "disable"}))
    return f"it is not a backend MuJoCo knows; valid: {valid}"


def configure(environ: MutableMapping[str, str] | None = None,
              find_library: Callable[[str], str | None] = ctypes.util.find_library,
              ) -> GLChoice:
    """Set ``MUJOCO_GL`` to a backend that loads here, or to ``disable``.

    A backend the user set is kept when it can load; unset, EGL is chosen, else OSMesa
    (with ``PYOPENGL_PLATFORM=osmesa``). Call before MuJoCo or dm_control is imported.

    Returns:
        The decision, with the reason when no backend can load.
    """
    environ = os.environ if environ is None else environ
    requested = environ.get("MUJOCO_GL")
    inherited = environ.get(PROBLEM_ENV)
    if inherited and requested is not None and requested.lower().strip() in DISABLED:
        return GLChoice(requested, requested, inherited)  # a parent's decision, kept
    if requested is not None:
        problem = backend_problem(requested, environ, find_library)
        if problem is None:
            if requested.lower().strip() == "osmesa":
                environ.setdefault("PYOPENGL_PLATFORM", "osmesa")
            return GLChoice(requested, requested, None)
        environ["MUJOCO_GL"] = "disable"
        environ[PROBLEM_ENV] = (f"MUJOCO_GL={requested} was asked for, but {problem}; set "
                                "another backend, or unset MUJOCO_GL")
        return GLChoice(requested, "disable", environ[PROBLEM_ENV])
    problems = []
    for backend in OFFSCREEN_LIBRARY:
        problem = backend_problem(backend, environ, find_library)
        if problem is None:
            environ["MUJOCO_GL"] = backend
            if backend == "osmesa":
                environ.setdefault("PYOPENGL_PLATFORM", "osmesa")
            return GLChoice(None, backend, None)
        problems.append(f"{backend}: {problem}")
    environ["MUJOCO_GL"] = "disable"
    environ[PROBLEM_ENV] = ("no offscreen OpenGL library is installed ("
                            + "; ".join(problems) + ")")
    return GLChoice(None, "disable", environ[PROBLEM_ENV])
