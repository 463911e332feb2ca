"""Offscreen rendering through EGL (Mesa on CPU machines), frames and written files."""

import imageio_ffmpeg
import numpy as np
import pytest

from wmr_mujoco.render.video import pick_scenario, render_scenario, render_to_file

pytestmark = pytest.mark.gl


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


def _peak_traced_bytes(fn):
    import tracemalloc

    tracemalloc.start()
    try:
        fn()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_render_memory_is_flat_in_clip_length(tmp_path):
    """Frames stream to the encoder: a clip 6 s longer costs no more frame memory.

    Holding the frames would add (2 − 0.5) s × 20 frames/s × 320 × 240 × 3 B = 6.9 MB
    (twice that with the stacked copy); the bound is half of it. What does grow with
    length — the stored states (750 steps × about 20 numbers × 8 B ≈ 0.12 MB for the
    disc) and the trails (30 points) — is far below it.
    """
    width, height, fps = 320, 240, 20
    frame_bytes = width * height * 3
    # A first render outside the measurement takes the one-time costs (imports, the GL
    # context's first use), which would otherwise hide growth in the shorter clip's peak.
    render_to_file("disc", tmp_path / "warm.mp4", width=width, height=height, fps=fps,
                   duration=0.2)
    peaks = {d: _peak_traced_bytes(lambda d=d: render_to_file(
        "disc", tmp_path / f"clip{d}.mp4", width=width, height=height, fps=fps,
        duration=d, hold=True)) for d in (0.5, 2.0)}
    held = (2.0 - 0.5) * fps * frame_bytes
    # Measured: 0.13 MB streamed; 7.0 MB with the frames held (the writer patched to
    # collect them), above the bound, so the test fails on a renderer that keeps frames.
    assert peaks[2.0] - peaks[0.5] < 0.5 * held, peaks
    assert len(_decode(tmp_path / "clip2.0.mp4")) == 40


def test_hold_keeps_the_last_input_past_the_scenario():
    from wmr_mujoco.render.video import clip_scenario

    s = pick_scenario("disc", "straight")
    held = clip_scenario(s, s.duration + 5.0, hold=True)
    assert held.duration == s.duration + 5.0
    np.testing.assert_array_equal(held.input_at(s.duration + 4.0), s.input_at(s.duration))
    with pytest.raises(ValueError, match=r"valid range is \(0, .*only with hold"):
        clip_scenario(s, s.duration + 5.0)


def test_coinciding_trails_both_show(tmp_path):
    """Two identical trails: the model's (red) shows as a rim around the simulated (green)."""
    import mujoco

    from wmr_mujoco.lookup import load
    from wmr_mujoco.render import rendering

    model = load("disc")
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    points = np.array([[0.0, -0.6, 0.003], [0.0, 0.6, 0.003]])
    with rendering.Filmer(model, 160, 120) as filmer:
        lift = np.array([0.0, 0.0, filmer.trail_width])
        image = filmer.frame(data, [
            (points, rendering.MODEL_RGBA, rendering.MODEL_TRAIL_SCALE),
            (points + lift, rendering.SIM_RGBA, rendering.SIM_TRAIL_SCALE)]).astype(int)
    r, g, b = image[..., 0], image[..., 1], image[..., 2]
    red = (r > 150) & (g < 90) & (b < 90)
    green = (g > 120) & (r < 90) & (b < 90)
    assert red.sum() > 20 and green.sum() > 20, (red.sum(), green.sum())


def test_a_png_is_the_last_frame(tmp_path):
    import mediapy

    out = render_to_file("disc", tmp_path / "still.png", width=64, height=48, fps=10,
                         duration=0.5)
    clip = render_scenario(pick_scenario("disc"), width=64, height=48, fps=10, duration=0.5)
    np.testing.assert_array_equal(mediapy.read_image(out)[..., :3], clip[-1])


def _no_stepping(monkeypatch):
    import mujoco

    def stepped(*args):
        raise AssertionError("simulated before the camera was checked")

    monkeypatch.setattr(mujoco, "mj_step", stepped)


@pytest.mark.parametrize("robot", ["disc", "whipple"])  # a kinematic run; a measurement's film
def test_a_bad_camera_is_refused_before_any_simulation(tmp_path, monkeypatch, robot):
    _no_stepping(monkeypatch)
    with pytest.raises(ValueError, match="camera 'nope' not in the model; valid cameras are: "
                       "track"):
        render_to_file(robot, tmp_path / "clip.mp4", width=64, height=48, fps=10,
                       duration=0.2, camera="nope")
    from wmr_mujoco.render.video import film_scenario

    with pytest.raises(ValueError, match="camera 'nope' not in the model"):
        film_scenario(pick_scenario(robot), lambda f: None, 64, 48, 10, camera="nope")
    assert list(tmp_path.rglob("*")) == []


def test_an_error_while_filming_comes_back_unchanged():
    """Only a diverging run is a SimulationDivergedError; the encoder's error is its own."""
    from wmr_mujoco.render.video import clip_scenario, film_scenario

    def full_disk(frame):
        raise OSError("no space left on device")

    with pytest.raises(OSError, match="no space left on device"):
        film_scenario(clip_scenario(pick_scenario("disc"), 0.2), full_disk, 64, 48, 10)


def test_all_clips_of_a_robot_are_written_where_its_entry_says(tmp_path, capsys):
    """``wmr render --all``: every clip the registry entry lists, named as it says."""
    from wmr_mujoco.cli import main
    from wmr_mujoco.robots import get_spec

    spec = get_spec("double_steer")
    assert main(["render", "--all", "double_steer", "--out", str(tmp_path), "-q"]) == 0
    files = sorted(p.name for p in tmp_path.iterdir())
    assert files == sorted(spec.clip_file(c) for c in spec.clips) == ["double_steer.gif"]
    assert f"wrote {tmp_path / 'double_steer.gif'}" in capsys.readouterr().out


@pytest.mark.parametrize("argv, message", [
    (["--all", "--scenario", "slalom"], "--all films each robot's listed clips; --scenario"),
    (["disc", "bicycle"], "render takes one robot, got 2: disc bicycle"),
    ([], "render takes one robot, got 0"),
    (["--all", "segway"], "unknown robot 'segway'"),
])
def test_render_arguments_are_checked_first(tmp_path, capsys, argv, message):
    from wmr_mujoco.cli import main

    assert main(["render", *argv, "--out", str(tmp_path)]) == 2
    assert message in capsys.readouterr().err
    assert not any(tmp_path.iterdir())


def test_an_encoder_failing_on_a_full_disk_is_one_line_and_exit_5(tmp_path, monkeypatch,
                                                                   capsys):
    """ffmpeg's failure (mediapy's ``RuntimeError: Error writing ...``, its stderr last)
    is an I/O error of the output file: exit 5, one line, no file left."""
    import contextlib

    from wmr_mujoco.cli import main
    from wmr_mujoco.render import rendering

    @contextlib.contextmanager
    def full_disk(path, width, height, fps):
        def write(frame):
            raise RuntimeError(f"Error writing '{path}': [out#0/mp4] Error submitting a "
                               "packet\nav_interleaved_write_frame(): No space left on device")
        yield write

    monkeypatch.setattr(rendering, "video_writer", full_disk)
    out = tmp_path / "clip.mp4"
    assert main(["render", "disc", "--out", str(out), "--duration", "0.2", "-q"]) == 5
    assert capsys.readouterr().err.strip().splitlines() == [
        "wmr: I/O error: the video encoder (ffmpeg) failed: av_interleaved_write_frame(): "
        f"No space left on device: {out}"]
    assert list(tmp_path.iterdir()) == []
