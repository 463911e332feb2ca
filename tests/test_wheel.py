"""The wheel works on its own: built, installed in a fresh environment, run elsewhere.

The environment gets this one's dependencies through a ``.pth`` line (no download) and
the wheel alone (``--no-deps --no-index``); the commands run from an unrelated folder,
with neither ``PYTHONPATH`` nor ``WMR_MODELS_DIR``, so the models can only come from the
installed package data.
"""

import os
import shutil
import site
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]


def _run(args, cwd, env, timeout=120):
    proc = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=timeout, check=False)
    assert proc.returncode == 0, f"{args}: {proc.stdout[-1500:]}{proc.stderr[-1500:]}"
    return proc


@pytest.mark.wheel
@pytest.mark.gl
def test_wheel_installs_and_runs_from_an_unrelated_folder(tmp_path):
    source = tmp_path / "source"
    shutil.copytree(REPO, source, ignore=shutil.ignore_patterns(
        ".git", ".venv", "build", "dist", "reports", "renders", "tests", "*.egg-info",
        "__pycache__", ".pytest_cache", ".ruff_cache"))
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "WMR_MODELS_DIR", "VIRTUAL_ENV")}
    wheels = tmp_path / "wheels"
    built = _run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "-v",
                  "-w", str(wheels), str(source)], tmp_path, env, timeout=180)
    assert "Deprecat" not in built.stdout + built.stderr  # setuptools says nothing
    wheel = next(wheels.glob("wmr_mujoco-*.whl"))

    venv = tmp_path / "venv"
    _run([sys.executable, "-m", "venv", "--without-pip", str(venv)], tmp_path, env)
    python = venv / "bin" / "python"
    purelib = _run([str(python), "-c", "import sysconfig; print(sysconfig.get_paths()"
                    "['purelib'])"], tmp_path, env).stdout.strip()
    # This environment's dependencies (mujoco, dm_control, ...) after the venv's own.
    Path(purelib, "deps.pth").write_text("\n".join(site.getsitepackages()) + "\n")
    _run([sys.executable, "-m", "pip", "--python", str(python), "install", "--quiet",
          "--no-deps", "--no-index", str(wheel)], tmp_path, env)

    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    where = _run([str(python), "-c", "import wmr_mujoco.models.paths as p; "
                  "print(p.__file__); print(p.MODELS_DIR)"], elsewhere, env).stdout.split()
    assert all(line.startswith(str(venv)) for line in where), where
    assert (Path(where[1]) / "omni3" / "scene.xml").is_file()
    wmr = str(venv / "bin" / "wmr")
    listed = _run([wmr, "list"], elsewhere, env).stdout
    assert all(robot in listed for robot in ("disc", "bicycle", "tricycle", "omni3"))
    validated = _run([wmr, "validate", "disc", "--scenario", "straight", "--quiet",
                      "--out", "reports"], elsewhere, env).stdout
    assert "1 of 1 scenarios pass" in validated
    _run([wmr, "render", "omni3", "--out", "clip.gif", "--duration", "0.4", "--fps", "5",
          "--width", "64", "--height", "48", "--quiet"], elsewhere, env)
    assert (elsewhere / "clip.gif").stat().st_size > 1000
