"""Offscreen rendering: a tracking camera, trajectory trails, and atomic media files.

Call :func:`wmr_mujoco.render.gl_backend.select_backend` before the first import of MuJoCo
to get the EGL → OSMesa fallback; importing this module uses whatever ``MUJOCO_GL``
is set (EGL by default, see :mod:`wmr_mujoco`).
"""

from __future__ import annotations

import contextlib
import itertools
import os
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco.atomic import atomic_path

#: Media suffixes :func:`write_media` can write.
VIDEO_SUFFIXES = (".mp4", ".gif")
IMAGE_SUFFIXES = (".png",)
#: Trail colours: simulated (MuJoCo) and analytic model.
SIM_RGBA = (0.1, 0.8, 0.2, 1.0)
MODEL_RGBA = (0.95, 0.2, 0.2, 1.0)
#: Largest frame size accepted (MuJoCo's offscreen buffer is sized to match).
MAX_SIZE = 4096
#: Trail radius relative to :attr:`Filmer.trail_width`: the model's trail is drawn wider
#: and the simulated one narrower and on top of it, so where the two coincide the model's
#: shows as a red rim around the green (equal capsules z-fight into dashes).
SIM_TRAIL_SCALE = 0.6
#: Shadow map size (texels a side) when shadows are off: MuJoCo allocates the map anyway.
NO_SHADOW_MAP = 16
MODEL_TRAIL_SCALE = 1.2


@dataclass(frozen=True)
class CameraSettings:
    """Tracking camera that follows the robot's base body.

    Attributes:
        distance: camera distance, in multiples of the robot's size (see
            :func:`robot_size`).
        azimuth: degrees, about the vertical.
        elevation: degrees (negative looks down).
        shadows: render shadows (about half the frame rate on a CPU).
        reflections: render the floor's reflections (about 2/3 of the frame rate).
    """

    distance: float = 3.5
    azimuth: float = 135.0
    elevation: float = -30.0
    shadows: bool = False
    reflections: bool = False


def check_size(width: int, height: int) -> None:
    """Raise ``ValueError`` unless ``width`` and ``height`` are in ``[16, MAX_SIZE]``."""
    for name, value in (("width", width), ("height", height)):
        if not isinstance(value, int) or not 16 <= value <= MAX_SIZE:
            raise ValueError(f"{name} = {value!r} pixels; valid range is [16, {MAX_SIZE}]")


def check_output_path(path: Path, suffixes: Sequence[str]) -> Path:
    """Validate an output path: known suffix and an existing, writable folder."""
    path = Path(path)
    if path.suffix.lower() not in suffixes:
        raise ValueError(f"output file {str(path)!r} has suffix {path.suffix!r}; "
                         f"valid suffixes are {', '.join(suffixes)}")
    folder = path.parent if str(path.parent) else Path(".")
    if not folder.is_dir():
        raise ValueError(f"output folder {str(folder)!r} does not exist; create it first "
                         "(wmr writes only into existing folders)")
    if not os.access(folder, os.W_OK):
        raise ValueError(f"output folder {str(folder)!r} is not writable")
    return path


def check_camera(model: mujoco.MjModel, camera: str) -> None:
    """Check that ``camera`` is ``"track"`` or a camera named in ``model``.

    Raises:
        ValueError: no such camera; the message lists the valid ones.
    """
    if camera == "track":
        return
    if not isinstance(camera, str) or mujoco.mj_name2id(
            model, mujoco.mjtObj.mjOBJ_CAMERA, camera) < 0:
        names = [model.camera(i).name for i in range(model.ncam)]
        raise ValueError(f"camera {camera!r} not in the model; valid cameras are: "
                         f"track{''.join(', ' + n for n in names)}")


def robot_size(model: mujoco.MjModel) -> float:
    """Largest distance from the ``base`` site to the surface of a robot geom, at qpos0."""
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    base = data.site_xpos[model.site("base").id]
    robot = model.geom_bodyid > 0
    reach = np.linalg.norm(data.geom_xpos[robot] - base, axis=1) + model.geom_rbound[robot]
    return float(np.max(reach))


def tracking_camera(model: mujoco.MjModel, settings: CameraSettings) -> mujoco.MjvCamera:
    """A camera that tracks the body carrying the ``base`` site."""
    cam = mujoco.MjvCamera()
    cam.type = mujoco.mjtCamera.mjCAMERA_TRACKING
    cam.trackbodyid = int(model.site_bodyid[model.site("base").id])
    cam.distance = settings.distance * robot_size(model)
    cam.azimuth = settings.azimuth
    cam.elevation = settings.elevation
    return cam


def add_polyline(scene: mujoco.MjvScene, points: np.ndarray, rgba: Sequence[float],
                 width: float) -> None:
    """Append line segments through ``points`` (N×3) to the scene's geoms."""
    rgba = np.asarray(rgba, dtype=np.float32)
    for a, b in itertools.pairwise(points):
        if scene.ngeom >= scene.maxgeom:
            return
        if np.allclose(a, b):
            continue
        geom = scene.geoms[scene.ngeom]
        mujoco.mjv_initGeom(geom, mujoco.mjtGeom.mjGEOM_CAPSULE, np.zeros(3), np.zeros(3),
                            np.zeros(9), rgba)
        mujoco.mjv_connector(geom, mujoco.mjtGeom.mjGEOM_CAPSULE, width, a, b)
        geom.category = mujoco.mjtCatBit.mjCAT_DECOR
        scene.ngeom += 1


class Filmer:
    """Offscreen renderer of one model with a tracking camera and trails.

    Use as a context manager; each :meth:`frame` returns an ``(height, width, 3)``
    uint8 image.
    """

    def __init__(self, model: mujoco.MjModel, width: int = 640, height: int = 480,
                 camera: CameraSettings | str = CameraSettings()) -> None:
        check_size(width, height)
        model.vis.global_.offwidth = max(model.vis.global_.offwidth, width)
        model.vis.global_.offheight = max(model.vis.global_.offheight, height)
        self.model = model
        self.trail_width = 0.02 * robot_size(model)
        if isinstance(camera, str):
            check_camera(model, camera)
            self.camera: mujoco.MjvCamera | str = camera
            settings = CameraSettings()
        else:
            self.camera = tracking_camera(model, camera)
            settings = camera
        if not settings.shadows:
            # The shadow map (shadowsize² texels: 64 MB at MuJoCo's default 4096, in main
            # memory with Mesa) is allocated even when shadows are off.
            model.vis.quality.shadowsize = min(model.vis.quality.shadowsize, NO_SHADOW_MAP)
        self.renderer = mujoco.Renderer(model, height=height, width=width, max_geom=20000)
        self.renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = settings.shadows
        self.renderer.scene.flags[mujoco.mjtRndFlag.mjRND_REFLECTION] = settings.reflections

    def frame(self, data: mujoco.MjData,
              trails: Sequence[tuple[np.ndarray, Sequence[float]]
                               | tuple[np.ndarray, Sequence[float], float]] = ()
              ) -> np.ndarray:
        """Render ``data`` with polylines ``(points N×3, rgba[, radius scale])`` on top.

        The image is MuJoCo's buffer, overwritten by the next frame: copy it to keep it.
        """
        self.renderer.update_scene(data, camera=self.camera)
        for points, rgba, *scale in trails:
            if len(points) > 1:
                add_polyline(self.renderer.scene, np.asarray(points), rgba,
                             self.trail_width * (scale[0] if scale else 1.0))
        return self.renderer.render()

    def close(self) -> None:
        """Free the GL context."""
        self.renderer.close()

    def __enter__(self) -> Filmer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def _ffmpeg() -> None:
    import imageio_ffmpeg
    import mediapy

    mediapy.set_ffmpeg(imageio_ffmpeg.get_ffmpeg_exe())


@contextlib.contextmanager
def video_writer(path: Path, width: int, height: int, fps: float = 30.0
                 ) -> Iterator[Callable[[np.ndarray], None]]:
    """Stream frames into an MP4 or GIF through ffmpeg, atomically.

    Yields a function that encodes one ``(height, width, 3)`` frame; no frame is kept,
    so memory does not grow with the clip's length. The file appears at ``path`` only
    when the block ends normally; on any exception or interrupt the temporary file is
    removed.
    """
    import mediapy

    path = check_output_path(Path(path), VIDEO_SUFFIXES)
    check_size(width, height)
    _ffmpeg()
    codec = "gif" if path.suffix.lower() == ".gif" else "h264"
    with atomic_path(path) as tmp, mediapy.VideoWriter(tmp, shape=(height, width), fps=fps,
                                                       codec=codec) as writer:
        yield writer.add_image


def write_media(path: Path, frames: Sequence[np.ndarray] | np.ndarray, fps: float = 30.0
                ) -> Path:
    """Write a PNG (one frame), MP4 or GIF atomically: a temporary file, then a rename.

    A failure leaves no file at ``path`` (nor a temporary one).
    """
    import mediapy

    path = check_output_path(Path(path), VIDEO_SUFFIXES + IMAGE_SUFFIXES)
    frames = np.asarray(frames)
    with atomic_path(path) as tmp:
        if path.suffix.lower() in IMAGE_SUFFIXES:
            mediapy.write_image(tmp, frames if frames.ndim == 3 else frames[0])
        else:
            _ffmpeg()
            codec = "gif" if path.suffix.lower() == ".gif" else "h264"
            mediapy.write_video(tmp, frames, fps=fps, codec=codec)
    return path
