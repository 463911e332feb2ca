"""wmr_mujoco.gl_env: a missing OpenGL backend breaks drawing only, never the imports.

Library look-ups are stubbed (``find_library``) so each machine a user may have is checked
here whatever this one has; the end-to-end cases run the command line in a subprocess
whose ``ctypes.util.find_library`` finds nothing, as on a machine without OpenGL.
"""

import subprocess
import sys

import pytest

from wmr_mujoco import gl_env


def _finder(*present):
    return lambda name: f"lib{name}.so" if name in present else None


@pytest.mark.parametrize("backend, env, present, problem", [
    ("egl", {}, ("EGL",), None),
    ("EGL ", {}, ("EGL",), None),
    ("egl", {}, (), "libEGL is not installed"),
    ("osmesa", {}, ("EGL",), "libOSMesa is not installed"),
    ("glfw", {}, ("EGL",), "no display"),
    ("glfw", {"DISPLAY": ":0"}, (), None),
    ("disable", {}, (), None),
    ("vulkan", {}, ("EGL",), "not a backend MuJoCo knows"),
])
def test_backend_problem(backend, env, present, problem):
    found = gl_env.backend_problem(backend, env, _finder(*present))
    assert found is None if problem is None else problem in found


@pytest.mark.parametrize("env, present, backend", [
    ({}, ("EGL", "OSMesa"), "egl"),
    ({}, ("OSMesa",), "osmesa"),
    ({}, (), "disable"),
    ({"MUJOCO_GL": "osmesa"}, ("OSMesa",), "osmesa"),
    ({"MUJOCO_GL": "osmesa"}, ("EGL",), "disable"),   # the machine
])
def test_configure_sets_a_loadable_backend_or_disables(env, present, backend):
    choice = gl_env.configure(env, _finder(*present))
    assert env["MUJOCO_GL"] == choice.backend == backend
    assert (choice.problem is None) == (backend != "disable")
    assert env.get("PYOPENGL_PLATFORM") == ("osmesa" if backend == "osmesa" else None)


#: Runs the command line with no OpenGL library to be found, like a machine without any.
NO_GL = ("import ctypes.util, sys; ctypes.util.find_library = lambda name: None\n"
         "from wmr_mujoco.cli import main\nsys.exit(main(sys.argv[1:]))\n")


def _wmr(args, env_gl, tmp_path):
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path)}
    if env_gl is not None:
        env["MUJOCO_GL"] = env_gl
    return subprocess.run([sys.executable, "-c", NO_GL, *args], env=env, cwd=tmp_path,
                          capture_output=True, text=True, timeout=300, check=False)


@pytest.mark.parametrize("env_gl", [None, "osmesa", "egl"])
def test_validation_runs_without_any_opengl(tmp_path, env_gl):
    proc = _wmr(["validate", "diffdrive", "--scenario", "straight", "--out",
                 str(tmp_path / "out"), "--quiet"], env_gl, tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "out" / "validation.json").exists()


def test_drawing_without_opengl_is_exit_3_in_one_line(tmp_path):
    proc = _wmr(["render", "diffdrive", "--out", str(tmp_path / "c.gif")], "osmesa", tmp_path)
    assert proc.returncode == 3
    assert proc.stderr.count("\n") == 1 and "libOSMesa is not installed" in proc.stderr
    assert not (tmp_path / "c.gif").exists()


def test_a_child_process_keeps_the_parents_reason():
    """Test workers and tools inherit MUJOCO_GL=disable; the reason comes with it."""
    env = {"MUJOCO_GL": "osmesa"}
    parent = gl_env.configure(env, _finder("EGL"))
    child = gl_env.configure(dict(env), _finder("EGL"))
    assert child.backend == "disable" and child.problem == parent.problem
