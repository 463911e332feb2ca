"""scripts/make-venv.sh: a virtual environment with pip, whatever the interpreter lacks.

A stub interpreter on a PATH of its own stands for Debian's python3 without python3-venv
(``venv`` fails for want of ``ensurepip``), with or without its own pip; each way out the
script takes is checked, and so is the one line it prints when none works.
"""

import shutil
import stat
import subprocess
import sys
from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "make-venv.sh"

#: A stub python3: what each module call does is set by the flags in its folder.
STUB = r"""#!/bin/bash
here=$(dirname "$0")
echo "$*" >> "$here/calls.log"
case "$1 $2" in
  "-m venv")
    [ "$3" = --without-pip ] && { mkdir -p "$4/bin"; exit 0; }
    [ -e "$here/ensurepip" ] || { mkdir -p "$3/bin"; exit 1; }
    mkdir -p "$3/bin"; touch "$3/bin/pip"; chmod +x "$3/bin/pip"; exit 0 ;;
  "-m pip")
    [ -e "$here/pip" ] || exit 1
    [ "$3" = --python ] && { touch "$(dirname "$4")/pip"; exit 0; }
    exit 0 ;;
esac
exit 1
"""


def _run(tmp_path: Path, *flags: str) -> tuple[subprocess.CompletedProcess, Path, list[str]]:
    shim = tmp_path / "bin"
    shim.mkdir()
    for tool in ("bash", "rm", "mkdir", "dirname", "touch", "chmod"):
        (shim / tool).symlink_to(shutil.which(tool))
    python = shim / "python3"
    python.write_text(STUB)
    python.chmod(python.stat().st_mode | stat.S_IXUSR)
    for flag in flags:
        (shim / flag).touch()
    venv = tmp_path / "venv"
    proc = subprocess.run([str(shim / "bash"), str(SCRIPT), str(python), str(venv)],
                          env={"PATH": str(shim)}, capture_output=True, text=True,
                          check=False)
    log = shim / "calls.log"
    return proc, venv, log.read_text().splitlines() if log.exists() else []


def test_venv_with_ensurepip_is_used_as_it_is(tmp_path):
    proc, venv, calls = _run(tmp_path, "ensurepip")
    assert proc.returncode == 0 and (venv / "bin" / "pip").exists()
    assert calls == [f"-m venv {venv}"]


def test_without_ensurepip_the_interpreters_pip_fills_a_bare_venv(tmp_path):
    proc, venv, calls = _run(tmp_path, "pip")
    assert proc.returncode == 0, proc.stderr
    assert "without ensurepip" in proc.stdout and (venv / "bin" / "pip").exists()
    assert calls[-1] == f"-m pip --python {venv}/bin/python install --quiet pip"


def test_without_ensurepip_or_pip_it_says_what_to_install(tmp_path):
    proc, venv, _ = _run(tmp_path)
    assert proc.returncode == 1 and not venv.exists()
    assert proc.stderr.count("\n") == 1 and "apt-get install python3-venv" in proc.stderr


@pytest.mark.skipif(sys.prefix == sys.base_prefix, reason="needs to run inside a venv")
def test_this_interpreter_makes_a_working_venv(tmp_path):
    """The real thing, with the interpreter that runs the tests' base Python."""
    base = Path(sys.base_prefix) / "bin" / "python3"
    proc = subprocess.run(["bash", str(SCRIPT), str(base), str(tmp_path / "v")],
                          capture_output=True, text=True, check=False, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert subprocess.run([str(tmp_path / "v" / "bin" / "python"), "-m", "pip", "--version"],
                          capture_output=True, check=False).returncode == 0
