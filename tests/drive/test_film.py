"""Filming a driven robot's run."""

from __future__ import annotations

from pathlib import Path

import imageio_ffmpeg
import mediapy
import numpy as np
import pytest

from wmr_mujoco.drive import make

#: Drawing tests: skipped, with the reason, where no OpenGL backend exists (the ``gl``
#: marker of the test suite's conftest).
pytestmark = pytest.mark.gl


def _read(path: Path) -> np.ndarray:
    """Decode with imageio-ffmpeg's reader (mediapy.read_video needs an older ffmpeg)."""
    gen = imageio_ffmpeg.read_frames(str(path))
    meta = next(gen)
    w, h = meta["size"]
    return np.array([np.frombuffer(f, np.uint8).reshape(h, w, 3) for f in gen])


@pytest.mark.parametrize("backend", ["mujoco", "kinematic"])
def test_films_the_recorded_run(tmp_path: Path, backend: str) -> None:
    robot = make("diffdrive", backend=backend)
    robot.reset()
    for _ in range(25):
        robot.step((0.5, 1.0))
    gif = robot.film(tmp_path / "run.gif", width=64, height=48, fps=10)
    frames = _read(gif)
    assert frames.shape == (6, 48, 64, 3)  # t = 0, 0.1, ..., 0.5 s
    assert np.abs(frames[0].astype(int) - frames[-1].astype(int)).mean() > 1  # it moved
    png = robot.film(tmp_path / "last.png", width=64, height=48, fps=10)
    assert mediapy.read_image(png).shape == (48, 64, 3)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["last.png", "run.gif"]


def test_bad_film_requests_raise_before_anything_is_written(tmp_path: Path) -> None:
    robot = make("diffdrive")
    robot.reset()
    with pytest.raises(ValueError, match="nothing to film"):
        robot.film(tmp_path / "a.mp4")
    robot.step((0.1, 0.0))
    with pytest.raises(ValueError, match="suffix '.avi'"):
        robot.film(tmp_path / "a.avi")
    with pytest.raises(ValueError, match="fps = 0"):
        robot.film(tmp_path / "a.mp4", fps=0)
    with pytest.raises(ValueError, match="width = 4"):
        robot.film(tmp_path / "a.mp4", width=4)
    with pytest.raises(ValueError, match="camera 'nope'"):
        robot.film(tmp_path / "a.mp4", camera="nope")
    assert list(tmp_path.iterdir()) == []
