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
               group: bool = False, stderr: Path | None = None) -> tuple[int, str]:
    """Start ``wmr argv``, wait (≤ 60 s) until ``ready()``, send ``sig``; exit code, stderr.

    ``group``: to the whole process group (``wmr`` and its helpers), as a terminal does.

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
        if group:
            os.killpg(proc.pid, sig)
        else:
            proc.send_signal(sig)
        _, err = proc.communicate(timeout=30)
        return proc.returncode, err if stderr is None else stderr.read_text()
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()


@pytest.mark.gl
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


@pytest.mark.gl
@pytest.mark.parametrize("sig, code", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_render_interrupted_from_a_terminal_leaves_no_file(tmp_path, sig, code):
    """A terminal's Ctrl-C goes to the whole process group: ffmpeg dies of it too, and
    its failure (mediapy's RuntimeError) is the interrupt, not an error of its own."""
    def ready() -> bool:
        if list(tmp_path.glob(".clip.*.mp4")):
            time.sleep(0.5)  # frames are flowing into ffmpeg
            return True
        return False

    returncode, err = _interrupt(
        ["render", "disc", "--out", str(tmp_path / "clip.mp4"), "--duration", "600",
         "--hold", "--fps", "10", "--width", "64", "--height", "48", "--quiet"],
        tmp_path, ready, sig, group=True)
    assert returncode == code, err
    assert err.strip().splitlines() == [
        f"wmr render: {'interrupted' if code == 130 else 'terminated'}; nothing written"]
    assert list(tmp_path.iterdir()) == []


def test_a_reader_that_goes_away_ends_the_output_quietly(tmp_path):
    """``wmr info omni3 | head -1``: the pipe closes before wmr writes; exit 141, no
    traceback (128 + SIGPIPE, what a shell reports for ``cat`` in the same place)."""
    env = {**os.environ, "PYTHONPATH": f"{SRC}{os.pathsep}{os.environ.get('PYTHONPATH', '')}"}
    read, write = os.pipe()
    os.close(read)  # the reader is gone before wmr has imported anything
    try:
        proc = subprocess.run([sys.executable, "-m", "wmr_mujoco.cli", "info", "omni3"],
                              stdout=write, stderr=subprocess.PIPE, text=True, env=env,
                              cwd=tmp_path, timeout=120)
    finally:
        os.close(write)
    assert (proc.returncode, proc.stderr) == (141, "")


def test_validate_interrupted_from_a_terminal_leaves_no_file(tmp_path, tmp_path_factory):
    """Ctrl-C to the whole process group, as a terminal sends it, mid-run."""
    out = tmp_path / "report"
    log = tmp_path_factory.mktemp("stderr") / "stderr.txt"
    returncode, err = _interrupt(
        ["validate", "whipple", "disc_free", "--out", str(out)], tmp_path,
        lambda: "[1/" in log.read_text(), signal.SIGINT, group=True, stderr=log)
    assert returncode == 130, err
    assert err.strip().splitlines()[-1] == "wmr validate: interrupted; nothing written"
    assert list(tmp_path.iterdir()) == []
