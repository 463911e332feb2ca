"""Filming a driven robot's recorded run: the robot, its physics trail and its model trail.

The run since the last reset is replayed, not simulated again: on the MuJoCo backend the
recorded generalised positions (one per control period) are drawn, with the ``base``
site's path in green and, in natural-command mode where the robot has a kinematic model,
the path of that model under the same recorded commands in red (the same trails as
``wmr render``, :mod:`wmr_mujoco.render.video`). On the kinematic backend the robot's
MuJoCo model is posed at each recorded pose and the model's path drawn in red.

Frames are taken every ``1/fps`` seconds of the run (the nearest recorded period) and
streamed to the encoder; the file appears only when complete
(:func:`wmr_mujoco.render.rendering.video_writer`).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from wmr_mujoco.loop.robot import Robot

#: Trail height above the floor, m (as ``wmr render``'s).
TRAIL_Z = 0.003
#: Highest frame rate.
MAX_FPS = 120


def _model_trail(robot: Robot) -> np.ndarray | None:
    """Path of the robot's kinematic model under the recorded commands (None: none)."""
    from wmr_mujoco.loop.build import build_robot

    if robot.backend == "kinematic":
        return np.array([s.pose[:2] for s in robot.history])
    if robot.mode != "command" or robot.spec.command.analytic(None) is None:
        return None
    twin = build_robot(robot.spec, backend="kinematic", control_period=robot.control_period,
                       params=robot.params)
    twin.reset(robot.history[0].pose)
    for command in robot.commands:
        twin.step(command)
    return np.array([s.pose[:2] for s in twin.history])


def film(robot: Robot, path: str | Path, width: int = 640, height: int = 480,
         fps: int = 30, camera: str = "track") -> Path:
    """Film ``robot``'s run since its last reset to ``path`` (.mp4, .gif; .png: last frame).

    Everything is checked before any frame is drawn; an interrupted or failed film leaves
    no file.

    Raises:
        ValueError: bad path, size, fps or camera, or nothing recorded yet.
        RenderingUnavailableError: no OpenGL backend works here.
    """
    from wmr_mujoco.render.gl_backend import select_backend

    select_backend()
    import mujoco

    import wmr_mujoco
    from wmr_mujoco.loop.readout import place
    from wmr_mujoco.render import rendering

    path = rendering.check_output_path(Path(path), rendering.VIDEO_SUFFIXES
                                       + rendering.IMAGE_SUFFIXES)
    rendering.check_size(width, height)
    if isinstance(fps, bool) or not isinstance(fps, int) or not 1 <= fps <= MAX_FPS:
        raise ValueError(f"fps = {fps!r}; valid range is integers [1, {MAX_FPS}]")
    history = robot.history
    if len(history) < 2:
        raise ValueError(f"nothing to film: {len(history)} recorded state(s); call "
                         "robot.reset() and robot.step() first")
    model = wmr_mujoco.load(robot.spec.name, robot.params)
    rendering.check_camera(model, camera)
    data = mujoco.MjData(model)
    qpos = list(getattr(robot, "qpos_history", ()))
    model_path = _model_trail(robot)
    lift = np.array([0.0, 0.0, TRAIL_Z])
    sim_path = np.array([s.pose[:2] for s in history])
    times = np.arange(0.0, float(history[-1].time) + 1e-9, 1.0 / fps)
    index = np.minimum(np.round(times / robot.control_period).astype(int), len(history) - 1)
    cam = rendering.CameraSettings() if camera == "track" else camera

    def frames(filmer: rendering.Filmer, sink: object) -> None:
        for k in index:
            if qpos:
                data.qpos[:] = qpos[k]
            else:
                mujoco.mj_resetData(model, data)
                place(model, data, history[k].pose)
            mujoco.mj_forward(model, data)
            trails = []
            if model_path is not None:  # wide and underneath
                trails.append((np.column_stack([model_path[:k + 1], np.zeros(k + 1)]) + lift,
                               rendering.MODEL_RGBA, rendering.MODEL_TRAIL_SCALE))
            if qpos:  # narrow, lifted on top
                sim = np.column_stack([sim_path[:k + 1], np.zeros(k + 1)]) + 2 * lift
                trails.append((sim, rendering.SIM_RGBA, rendering.SIM_TRAIL_SCALE))
            sink(filmer.frame(data, trails))  # type: ignore[operator]

    with rendering.Filmer(model, width, height, cam) as filmer:
        if path.suffix.lower() in rendering.IMAGE_SUFFIXES:
            last: list[np.ndarray] = []
            frames(filmer, lambda f: last.__setitem__(slice(None), [f.copy()]))
            return rendering.write_media(path, last[-1])
        with rendering.video_writer(path, width, height, fps) as write:
            frames(filmer, write)
    return path
