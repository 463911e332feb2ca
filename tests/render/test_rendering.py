"""Rendering helpers that need no GL context: checks, camera reach, trails, atomic writes."""

import mujoco
import numpy as np
import pytest

from wmr_mujoco.render.rendering import (
    MAX_SIZE,
    add_polyline,
    check_camera,
    check_output_path,
    check_size,
    robot_size,
    video_writer,
    write_media,
)

pytestmark = pytest.mark.gl

XML = """
<mujoco>
  <worldbody>
    <geom type="plane" size="5 5 0.1"/>
    <camera name="overhead" pos="0 0 3"/>
    <body name="robot" pos="0 0 0.2">
      <freejoint/>
      <site name="base"/>
      <geom type="sphere" size="0.1" pos="0.3 0.4 0"/>
      <geom type="box" size="0.05 0.05 0.05"/>
    </body>
  </worldbody>
</mujoco>
"""


@pytest.fixture
def model() -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(XML)


@pytest.mark.parametrize("width, height, bad", [(15, 100, "width = 15"),
                                                (100, MAX_SIZE + 1, f"height = {MAX_SIZE + 1}"),
                                                (100.0, 100, "width = 100.0")])
def test_sizes_outside_the_range_are_refused(width, height, bad):
    with pytest.raises(ValueError, match=f"{bad} pixels; valid range is \\[16, {MAX_SIZE}\\]"):
        check_size(width, height)


def test_output_path_checks(tmp_path):
    assert check_output_path(tmp_path / "a.MP4", (".mp4",)) == tmp_path / "a.MP4"
    with pytest.raises(ValueError, match=r"suffix '\.avi'; valid suffixes are \.mp4, \.gif"):
        check_output_path(tmp_path / "a.avi", (".mp4", ".gif"))
    with pytest.raises(ValueError, match="does not exist; create it first"):
        check_output_path(tmp_path / "missing" / "a.mp4", (".mp4",))


def test_cameras(model):
    check_camera(model, "track")
    check_camera(model, "overhead")
    with pytest.raises(ValueError, match="camera 'side' not in the model; valid cameras are: "
                                         "track, overhead"):
        check_camera(model, "side")


def test_robot_size_is_the_farthest_geom_surface_from_the_base(model):
    # Sphere centre 0.5 m from the base (3-4-5), radius 0.1; the box's bounding sphere is
    # smaller. The plane belongs to the world body and does not count.
    assert robot_size(model) == pytest.approx(0.5 + 0.1)


def test_polyline_skips_repeated_points_and_stops_at_capacity(model):
    scene = mujoco.MjvScene(model, maxgeom=3)
    points = np.array([[0, 0, 0], [1, 0, 0], [1, 0, 0], [1, 1, 0], [2, 1, 0], [3, 1, 0.0]])
    add_polyline(scene, points, (1, 0, 0, 1), 0.01)
    assert scene.ngeom == 3  # 4 distinct segments, capacity 3
    first = scene.geoms[0]
    assert first.type == mujoco.mjtGeom.mjGEOM_CAPSULE
    np.testing.assert_allclose(first.pos, [0.5, 0.0, 0.0], atol=1e-6)
    assert first.size[2] == pytest.approx(0.5)  # capsule half-length: half the segment


def test_media_are_written_whole_or_not_at_all(tmp_path):
    frame = np.zeros((32, 48, 3), np.uint8)
    png = write_media(tmp_path / "f.png", frame)
    assert png.stat().st_size > 0
    target = tmp_path / "clip.gif"
    with pytest.raises(RuntimeError, match="interrupted"), \
            video_writer(target, 48, 32, fps=5) as add:
        add(frame)
        raise RuntimeError("interrupted")
    assert list(tmp_path.iterdir()) == [png]
    with video_writer(target, 48, 32, fps=5) as add:
        for k in range(3):
            add(np.full((32, 48, 3), 80 * k, np.uint8))
    assert target.stat().st_size > 0 and sorted(p.name for p in tmp_path.iterdir()) == \
        ["clip.gif", "f.png"]
