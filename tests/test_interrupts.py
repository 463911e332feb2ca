"""Ctrl-C and SIGTERM end a command with one line, exit 130/143, and leave no file."""

import contextlib
import os
import signal
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"


def _default_sigint() -> None:
    """In the child, before exec: Ctrl-C as a terminal gives it. A shell that starts the
    tests in the background ignores SIGINT, the child would inherit that, and Python keeps
    an ignored SIGINT ignored (no KeyboardInterrupt)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def _interrupt(argv: list[str], cwd: Path, ready: Callable[[], bool], sig: int,
               stderr: Path | None = None) -> tuple[int, str]:
    """Start ``wmr argv``, wait (≤ 60 s) until ``ready()``, send ``sig``; exit code, stderr.

    The child runs in its own session, which is killed whatever happens, so that a failed
    test leaves no process behind (a render of 600 s would otherwise run on). ``stderr``:
    a file for the child's stderr (so that ``ready`` can read its progress lines).
    """
    env = {**os.environ, "PYTHONPATH": f"{SRC}{os.pathsep}{os.environ.get('PYTHONPATH', '')}"}
    proc = subprocess.Popen([sys.executable, "-m", "wmr_mujoco.cli", *argv], cwd=cwd,
                            env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE if stderr is None else stderr.open("w"),
                            text=True, preexec_fn=_default_sigint, start_new_session=True)
    try:
        deadline = time.monotonic() + 60
        while not ready() and time.monotonic() < deadline:
            assert proc.poll() is None, proc.communicate()
            time.sleep(0.05)
        proc.send_signal(sig)
        _, err = proc.communicate(timeout=30)
        return proc.returncode, err if stderr is None else stderr.read_text()
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()


@pytest.mark.parametrize("sig, code", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_interrupted_render_leaves_no_file(tmp_path, sig, code):
    # A clip far longer than the test waits: the signal always arrives mid-render. The
    # temporary video appears once the writer is open, before the first frame.
    def ready() -> bool:
        if list(tmp_path.glob(".clip.*.mp4")):
            time.sleep(0.2)
            return True
        return False

    returncode, err = _interrupt(
        ["render", "disc", "--out", str(tmp_path / "clip.mp4"), "--duration", "600",
         "--hold", "--fps", "10", "--width", "64", "--height", "48", "--quiet"],
        tmp_path, ready, sig)
    assert returncode == code, err
    assert err.strip().splitlines() == [
        f"wmr render: {'interrupted' if code == 130 else 'terminated'}; nothing written"]
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("sig, code", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_interrupted_validate_leaves_no_file(tmp_path, tmp_path_factory, sig, code):
    out = tmp_path / "report"
    log = tmp_path_factory.mktemp("stderr") / "stderr.txt"
    # The first scenario's progress line (no terminal: one line per result): the run is
    # under way and most scenarios are still to run.
    returncode, err = _interrupt(
        ["validate", "whipple", "disc_free", "--out", str(out)], tmp_path,
        lambda: "[1/" in log.read_text(), sig, stderr=log)
    assert returncode == code, err
    assert err.strip().splitlines()[-1] == (
        f"wmr validate: {'interrupted' if code == 130 else 'terminated'}; nothing written")
    assert list(tmp_path.iterdir()) == []
