"""scripts/install-system-deps.sh: rendering packages are offered, never required.

The script is run against stubs on a PATH of its own (a shim folder): ``ldconfig`` lists
the libraries of the machine imagined, ``apt-get`` answers as an archive would (and logs
what it was asked), ``id`` and ``sudo`` say who runs it. So each case a fresh machine can
present is checked without touching the system: the CI image (Mesa's EGL, no OSMesa), an
archive that no longer serves the installed Mesa's version, a user without root, a machine
without apt.
"""

import shutil
import stat
import subprocess
from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "install-system-deps.sh"
EGL_MESA = ["libEGL.so.1 ", "libEGL_mesa.so.0 ", "libGL.so.1 "]
#: Tools the script uses besides the stubbed ones, linked into the shim folder.
TOOLS = ("bash", "grep", "awk", "sort", "tr", "tail", "cat", "sed")
MISSING_VERSION = "E: Version '22.3.6-1+deb12u1' for 'libosmesa6' was not found"


def _stub(folder: Path, name: str, body: str) -> None:
    path = folder / name
    path.write_text("#!/bin/bash\n" + body + "\n")
    path.chmod(path.stat().st_mode | stat.S_IXUSR)


def _run(tmp_path: Path, libs: list[str], dri: bool = True, uid: int = 0,
         sudo: str | None = None, apt: bool = True, plan: str = "Inst libegl1 (1.6.0-1)",
         plan_rc: int = 0, ensurepip: bool = True,
         ) -> tuple[subprocess.CompletedProcess, list[str]]:
    """Run the script on an imagined machine; return its result and the apt calls."""
    shim, log, dri_dir = tmp_path / "bin", tmp_path / "apt.log", tmp_path / "dri"
    shim.mkdir()
    dri_dir.mkdir()
    for tool in TOOLS:
        (shim / tool).symlink_to(shutil.which(tool))
    if dri:
        (dri_dir / "swrast_dri.so").touch()
    listing = "".join(f"\t{lib}(libc6,x86-64) => /usr/lib/{lib.strip()}\\n" for lib in libs)
    _stub(shim, "ldconfig", f'printf "{listing}"')
    _stub(shim, "id", f"echo {uid}")
    _stub(shim, "python3", f"exit {0 if ensurepip else 1}")  # `import venv, ensurepip`
    if sudo == "nopasswd":
        _stub(shim, "sudo", f'[ "$1" = -n ] && shift; [ "$1" = true ] && exit 0\n'
                            f'echo "sudo $*" >> {log}; "$@"')
    elif sudo == "password":
        _stub(shim, "sudo", "echo 'sudo: a password is required' >&2; exit 1")
    if apt:
        _stub(shim, "apt-get", f'echo "$*" >> {log}\n'
                               f'[ "$1" = -s ] && {{ printf "%s\\n" "{plan}"; exit {plan_rc}; }}\n'
                               "exit 0")
    env = {"PATH": str(shim), "WMR_DRI_DIR": str(dri_dir), "HOME": str(tmp_path)}
    proc = subprocess.run([str(shim / "bash"), str(SCRIPT)], env=env, capture_output=True,
                          text=True, check=False)
    return proc, (log.read_text().splitlines() if log.exists() else [])


@pytest.mark.parametrize("libs, dri", [
    (EGL_MESA, True),                                       # the CI image: EGL, no OSMesa
    (["libEGL.so.1 ", "libEGL_nvidia.so.0 ", "libGL.so.1 "], False),   # NVIDIA's EGL
    (["libOSMesa.so.8 "], False),                           # OSMesa alone
])
def test_a_working_offscreen_stack_asks_apt_nothing(tmp_path, libs, dri):
    proc, calls = _run(tmp_path, libs, dri=dri)
    assert (proc.returncode, calls, proc.stderr) == (0, [], "")


def test_a_python_without_ensurepip_gets_python3_venv(tmp_path):
    """Debian's python3 without python3-venv: offered, beside a working EGL."""
    proc, calls = _run(tmp_path, EGL_MESA, ensurepip=False)
    assert proc.returncode == 0, proc.stderr
    assert calls[-1] == "install -y -qq --no-upgrade --no-install-recommends python3-venv"


def test_missing_egl_is_installed_unpinned_as_the_archive_serves_it(tmp_path):
    proc, calls = _run(tmp_path, ["libGL.so.1 "], dri=False)
    assert proc.returncode == 0, proc.stderr
    wanted = "--no-upgrade --no-install-recommends libegl1 libegl-mesa0 libgl1-mesa-dri"
    assert calls == ["update -qq", f"-s install {wanted}", f"install -y -qq {wanted}"]
    assert not any("=" in c for c in calls)  # no version pinned


@pytest.mark.parametrize("plan, plan_rc, said", [
    (MISSING_VERSION, 100, MISSING_VERSION),                 # the archive moved on
    ("E: Unable to locate package libegl-mesa0", 100, "Unable to locate"),
    ("Inst libglapi-mesa [22.3.6-1] (22.3.6-1+deb12u2 Debian:12)\nInst libegl-mesa0", 0,
     "would upgrade or remove libglapi-mesa"),
])
def test_apt_that_cannot_help_leaves_one_line_and_success(tmp_path, plan, plan_rc, said):
    proc, calls = _run(tmp_path, ["libEGL.so.1 ", "libGL.so.1 "], plan=plan, plan_rc=plan_rc)
    assert proc.returncode == 0
    assert not any(c.startswith("install") for c in calls)
    assert len(proc.stderr.strip().splitlines()) == 1 and said in proc.stderr


@pytest.mark.parametrize("sudo", [None, "password"])
def test_a_user_without_root_gets_one_line_and_no_apt(tmp_path, sudo):
    proc, calls = _run(tmp_path, [], dri=False, uid=1000, sudo=sudo)
    assert proc.returncode == 0 and calls == []
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and "no root" in lines[0] and "apt-get install libegl1" in lines[0]


def test_password_less_sudo_is_used(tmp_path):
    proc, calls = _run(tmp_path, [], dri=False, uid=1000, sudo="nopasswd")
    assert proc.returncode == 0, proc.stderr
    assert calls[0] == "sudo apt-get update -qq" and calls[-1].startswith("install -y")


def test_a_machine_without_apt_gets_one_line(tmp_path):
    proc, calls = _run(tmp_path, [], dri=False, apt=False)
    assert proc.returncode == 0 and calls == []
    assert "no apt-get here" in proc.stderr and len(proc.stderr.strip().splitlines()) == 1

