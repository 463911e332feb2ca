"""Offscreen rendering through EGL (Mesa on CPU machines), frames and written files."""

import imageio_ffmpeg
import numpy as np
import pytest

from wmr_mujoco.render.video import pick_scenario, render_scenario, render_to_file


def _decode(path):
    """Decode with imageio-ffmpeg's reader (mediapy.read_video needs an older ffmpeg)."""
    gen = imageio_ffmpeg.read_frames(str(path))
    meta = next(gen)
    w, h = meta["size"]
    return [np.frombuffer(f, np.uint8).reshape(h, w, 3) for f in gen]


@pytest.fixture(scope="module")
def frames():
    return render_scenario(pick_scenario("disc"), width=160, height=120, fps=10, duration=1.0)


def test_frame_count_and_size(frames):
    # One frame every 1/fps of simulated time over 1 s, the first at the first step.
    assert frames.shape == (10, 120, 160, 3) and frames.dtype == np.uint8


def test_frames_are_not_blank(frames):
    assert all(f.std() > 10 for f in frames)


def test_robot_moves_between_first_and_last_frame(frames):
    assert np.abs(frames[0].astype(int) - frames[-1].astype(int)).mean() > 2


@pytest.mark.parametrize("suffix", [".mp4", ".gif"])
def test_written_file_decodes_to_the_frame_count(tmp_path, suffix):
    out = render_to_file("omni3", tmp_path / f"clip{suffix}", width=160, height=120, fps=10,
                         duration=0.5)
    decoded = _decode(out)
    assert len(decoded) == 5 and decoded[0].shape == (120, 160, 3)
    assert [p.name for p in tmp_path.iterdir()] == [f"clip{suffix}"]


@pytest.mark.parametrize("kwargs, match", [
    ({"robot": "unicycle"}, "unknown robot 'unicycle'"),
    ({"out": "missing/clip.mp4"}, "output folder .* does not exist"),
    ({"out": "clip.avi"}, "suffix '.avi'"),
    ({"width": 8}, r"width = 8 pixels; valid range is \[16, 4096\]"),
    ({"height": 100000}, "height = 100000"),
    ({"scenario": "loop"}, "no scenario 'loop' for 'disc'"),
    ({"fps": 0}, "fps = 0"),
])
def test_bad_input_is_clear_and_leaves_no_file(tmp_path, monkeypatch, kwargs, match):
    monkeypatch.chdir(tmp_path)
    args = {"robot": "disc", "out": "clip.mp4", "width": 64, "height": 48, "fps": 10,
            "duration": 0.2} | kwargs
    with pytest.raises(ValueError, match=match):
        render_to_file(**args)
    assert list(tmp_path.rglob("*")) == []


def test_a_free_run_measurement_is_filmed():
    """The Whipple push at 3 m/s (a free run from its start state): one frame per 1/fps
    over 1 s, the bicycle leaning more and more (the frames change)."""
    frames = render_scenario(pick_scenario("whipple", "push at 3 m/s"), width=160,
                             height=120, fps=10, duration=1.0)
    assert frames.shape == (10, 120, 160, 3)
    assert np.abs(frames[0].astype(int) - frames[-1].astype(int)).mean() > 2


def test_a_measurement_without_a_film_is_refused_naming_the_filmable_ones():
    with pytest.raises(ValueError, match="whipple/critical speeds is a measurement without a "
                                         "film; scenarios that can be rendered: "
                                         "'push at 4.6 m/s'"):
        pick_scenario("whipple", "critical speeds")


def test_a_measurement_is_filmed_from_its_own_runs():
    """disc_free's steady precession: frames at fps over the duration, the disc moving."""
    got = render_scenario(pick_scenario("disc_free", "steady precession"), width=64,
                          height=48, fps=5, duration=1.0)
    assert got.shape == (5, 48, 64, 3)
    assert np.abs(got[0].astype(int) - got[-1].astype(int)).mean() > 2


def test_a_measurement_without_a_film_is_refused():
    with pytest.raises(ValueError, match="measurement without a film; scenarios that can "
                                         "be rendered: .*'sinusoidal steering'"):
        pick_scenario("disc", "sliding wheel")
