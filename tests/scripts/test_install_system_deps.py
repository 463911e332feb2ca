"""scripts/install-system-deps.sh installs only what is missing and upgrades nothing.

apt, dpkg, ldconfig, python3 and id are replaced by stubs on PATH (a shim folder), so the
script's decisions are checked without touching the system.
"""

import os
import stat
import subprocess
from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "install-system-deps.sh"
ALL_LIBS = ["libEGL.so.1 ", "libEGL_mesa.so.0 ", "libGL.so.1 ", "libOSMesa.so.6 "]
MESA = "24.2.8-1~bpo12+1"


def _stub(folder: Path, name: str, body: str) -> None:
    path = folder / name
    path.write_text("#!/bin/bash\n" + body + "\n")
    path.chmod(path.stat().st_mode | stat.S_IXUSR)


def _run(tmp_path: Path, libs: list[str], plan: str = "", dri: bool = True,
         installed_mesa: str | None = MESA) -> tuple[subprocess.CompletedProcess, list[str]]:
    shim, log, dri_dir = tmp_path / "bin", tmp_path / "apt.log", tmp_path / "dri"
    shim.mkdir()
    dri_dir.mkdir()
    if dri:
        (dri_dir / "swrast_dri.so").touch()
    listing = "".join(f"\t{lib}(libc6,x86-64) => /usr/lib/{lib.strip()}\\n" for lib in libs)
    _stub(shim, "ldconfig", f'printf "{listing}"')
    _stub(shim, "python3", "exit 0")
    _stub(shim, "id", "echo 0")
    mesa = (f'[ "$3" = libglapi-mesa ] && {{ echo -n "install ok installed {installed_mesa}"; '
            'exit 0; }; exit 1') if installed_mesa else "exit 1"
    _stub(shim, "dpkg-query", mesa)
    _stub(shim, "apt-get", f'echo "$*" >> {log}\n[ "$1" = -s ] && printf "%s\\n" "{plan}"\nexit 0')
    env = {**os.environ, "PATH": f"{shim}:{os.environ['PATH']}", "WMR_DRI_DIR": str(dri_dir)}
    proc = subprocess.run(["bash", str(SCRIPT)], env=env, capture_output=True, text=True,
                          check=False)
    return proc, (log.read_text().splitlines() if log.exists() else [])


def test_nothing_missing_calls_no_apt(tmp_path):
    proc, calls = _run(tmp_path, ALL_LIBS)
    assert proc.returncode == 0 and calls == []


def test_missing_mesa_package_is_pinned_to_the_installed_mesa(tmp_path):
    libs = [lib for lib in ALL_LIBS if "OSMesa" not in lib]
    proc, calls = _run(tmp_path, libs, plan=f"Inst libosmesa6 ({MESA} Debian:12)")
    assert proc.returncode == 0, proc.stderr
    pinned = f"--no-upgrade --no-install-recommends libosmesa6={MESA}"
    assert calls == ["update -qq", f"-s install {pinned}", f"install -y -qq {pinned}"]


def test_non_mesa_package_is_not_pinned_and_several_are_asked_together(tmp_path):
    libs = [lib for lib in ALL_LIBS if "libGL.so" not in lib]
    proc, calls = _run(tmp_path, libs, dri=False)
    assert proc.returncode == 0, proc.stderr
    assert calls[-1] == (f"install -y -qq --no-upgrade --no-install-recommends libgl1 "
                         f"libgl1-mesa-dri={MESA}")


@pytest.mark.parametrize("line, package", [
    ("Inst libglapi-mesa [24.2.8-1] (25.0.7-2 Debian:13)", "libglapi-mesa"),
    ("Remv libgbm1 [24.2.8-1]", "libgbm1"),
])
def test_an_install_that_would_change_installed_packages_stops_before_installing(
        tmp_path, line, package):
    libs = [lib for lib in ALL_LIBS if "OSMesa" not in lib]
    proc, calls = _run(tmp_path, libs, plan=f"{line}\nInst libosmesa6 ({MESA} Debian:12)")
    assert proc.returncode == 1
    assert f"would upgrade or remove installed packages:  {package}" in proc.stderr
    assert not any(c.startswith("install") for c in calls)


def test_without_any_mesa_installed_nothing_is_pinned(tmp_path):
    proc, calls = _run(tmp_path, [], installed_mesa=None)
    assert proc.returncode == 0, proc.stderr
    assert calls[-1].endswith("libegl1 libegl-mesa0 libgl1 libosmesa6")
