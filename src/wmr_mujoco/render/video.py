"""Videos of validation scenarios with the analytic trajectory drawn beside the physics.

Kinematic and dynamic scenarios are filmed through the runner; a measurement scenario
through its own ``film`` (the runs it measures, step by step), with the physics trail
and, where the scenario gives one, its analytic path. Frames stream to the encoder.

Call :func:`wmr_mujoco.render.gl_backend.select_backend` before MuJoCo is first imported (the
``wmr render`` command does) to get the EGL → OSMesa fallback.
"""

from __future__ import annotations

import dataclasses
import errno
from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco.lookup import load
from wmr_mujoco.progress import bar
from wmr_mujoco.render import rendering
from wmr_mujoco.robots import get_spec
from wmr_mujoco.sim.engine import Engine, simulate
from wmr_mujoco.sim.stepping import SimulationDivergedError
from wmr_mujoco.validation.adapters import Adapter
from wmr_mujoco.validation.runner import prepare
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind
from wmr_mujoco.validation.signals import Held

#: Trail height above the floor, m.
TRAIL_Z = 0.003


def pick_scenario(robot: str, name: str | None = None) -> Scenario:
    """The named scenario of ``robot`` (default: its render scenario, else first kinematic).

    Raises:
        ValueError: unknown robot, a robot without kinematic scenarios, no such
            scenario (the message lists the valid ones), or a measurement scenario
            without a film.
    """
    spec = get_spec(robot)
    name = name or spec.render_scenario
    if name is not None:
        scenario = spec.scenario(name)
        if scenario.kind is ScenarioKind.MEASUREMENT and scenario.film is None:
            filmable = [s.name for s in spec.scenarios
                        if s.kind is not ScenarioKind.MEASUREMENT or s.film is not None]
            raise ValueError(f"{scenario.key} is a measurement without a film; scenarios "
                             f"that can be rendered: {', '.join(map(repr, filmable))}")
        return scenario
    options = [s for s in spec.scenarios if s.kind is ScenarioKind.KINEMATIC]
    if not options:
        raise ValueError(f"robot {robot!r} has no kinematic scenario to render")
    return options[0]


#: Longest clip, s: an hour of 30 frames/s, far past any scenario held at its end.
MAX_DURATION = 3600.0


def clip_scenario(scenario: Scenario, duration: float | None = None, hold: bool = False
                  ) -> Scenario:
    """The scenario cut to ``duration``, or held at its last input up to ``duration``.

    Raises:
        ValueError: ``duration`` outside ``(0, scenario.duration]`` (``(0, MAX_DURATION]``
            with ``hold``), named with the valid range.
    """
    if duration is None:
        return scenario
    high = MAX_DURATION if hold else scenario.duration
    if not (isinstance(duration, (int, float)) and 0 < duration <= high):
        extra = "" if hold else " (longer only with hold: the last input kept)"
        raise ValueError(f"duration = {duration!r} s; valid range is (0, {high:g}] for "
                         f"{scenario.key}{extra}")
    if duration > scenario.duration:
        inputs = tuple(Held(sig, scenario.duration) for sig in scenario.inputs)
        return dataclasses.replace(scenario, inputs=inputs, duration=duration)
    return dataclasses.replace(scenario, duration=duration)


def _check_fps(fps: int) -> None:
    if not isinstance(fps, int) or not 1 <= fps <= 120:
        raise ValueError(f"fps = {fps!r}; valid range is integers [1, 120]")


def film_scenario(scenario: Scenario, on_frame: Callable[[np.ndarray], None],
                  width: int = 640, height: int = 480, fps: int = 30,
                  camera: str = "track") -> int:
    """Simulate ``scenario`` and hand each frame to ``on_frame``; return the frame count.

    Frames are drawn every ``1/fps`` of simulated time, the simulated path of the base in
    green and the analytic model's in red (a measurement scenario: the runs of its
    ``film``), and handed over at once, never kept: memory does not grow with the clip's
    length beyond the trails' points. A frame is valid only
    during the call (the renderer reuses its buffer). A progress bar runs on a terminal.

    The camera is checked against the robot's model before anything is simulated; an
    exception from the simulation or from ``on_frame`` (e.g. the encoder) comes back
    unchanged.

    Raises:
        ValueError: bad size, fps or camera.
        SimulationDivergedError: the run diverged.
    """
    rendering.check_size(width, height)
    _check_fps(fps)
    model = load(scenario.robot)
    rendering.check_camera(model, camera)
    if scenario.kind is ScenarioKind.MEASUREMENT:
        return _film_measurement(scenario, on_frame, width, height, fps, camera)
    sim_trail: list[np.ndarray] = []
    model_trail: list[np.ndarray] = []
    state: dict[str, object] = {"count": 0}
    progress_bar = bar(int(scenario.duration * fps) + 1, f"wmr render {scenario.key}",
                       unit="frame")

    def observe(model: mujoco.MjModel, data: mujoco.MjData, x: np.ndarray,
                adapter: Adapter) -> None:
        if "filmer" not in state:
            cam = rendering.CameraSettings() if camera == "track" else camera
            state["filmer"] = rendering.Filmer(model, width, height, cam)
            state["next"] = data.time
        if data.time + 1e-9 < state["next"]:
            return
        state["next"] = float(state["next"]) + 1.0 / fps
        site = data.site_xpos[model.site("base").id]
        sim_trail.append(np.array([site[0], site[1], TRAIL_Z]))
        if adapter.state_names[:2] == ("x", "y"):
            model_trail.append(np.array([x[0], x[1], TRAIL_Z]))
        filmer = state["filmer"]
        on_frame(filmer.frame(  # type: ignore[union-attr]
            data, _trails(sim_trail, np.asarray(model_trail),
                          filmer.trail_width)))  # type: ignore[union-attr]
        state["count"] = int(state["count"]) + 1  # type: ignore[call-overload]
        progress_bar.update()

    try:
        prep = prepare(get_spec(scenario.robot), scenario, model=model)

        def on_step(k: int) -> None:
            observe(prep.model, prep.data, prep.analytic[k + 1], prep.adapter)

        simulate(prep.model, prep.data, prep.controls, Engine.LOOP, on_step)
    except SimulationDivergedError as err:
        raise SimulationDivergedError(f"{scenario.key}: {err}") from err
    finally:
        progress_bar.close()
        if "filmer" in state:
            state["filmer"].close()  # type: ignore[union-attr]
    return int(state["count"])  # type: ignore[call-overload]


def render_scenario(scenario: Scenario, width: int = 640, height: int = 480, fps: int = 30,
                    camera: str = "track", duration: float | None = None,
                    hold: bool = False) -> np.ndarray:
    """Simulate ``scenario`` and return its frames ``(n, height, width, 3)``, in memory.

    For short clips and tests; :func:`render_to_file` streams instead.

    Raises:
        ValueError: bad size, fps, duration or camera.
        SimulationDivergedError: the run diverged.
    """
    rendering.check_size(width, height)
    _check_fps(fps)
    frames: list[np.ndarray] = []
    film_scenario(clip_scenario(scenario, duration, hold), lambda f: frames.append(f.copy()),
                  width, height, fps, camera)
    return np.asarray(frames)


def render_to_file(robot: str, out: Path, scenario: str | None = None, width: int = 640,
                   height: int = 480, fps: int = 30, camera: str = "track",
                   duration: float | None = None, hold: bool = False) -> Path:
    """Render a scenario of ``robot`` to ``out`` (.mp4 or .gif), streamed and atomic.

    A ``.png`` gets the last frame alone (a still of the whole trail).

    Every argument is checked before anything is simulated; frames go to the encoder as
    they are drawn (memory flat in the clip's length); a failure or an interrupt leaves
    no file. ``hold`` allows a ``duration`` past the scenario's end, keeping its last
    input.

    Raises:
        ValueError: bad output path, size, fps, scenario, duration or camera.
        SimulationDivergedError: the run diverged.
        OSError: the file could not be written (a full disk; the encoder failing).
    """
    out = rendering.check_output_path(Path(out), rendering.VIDEO_SUFFIXES
                                      + rendering.IMAGE_SUFFIXES)
    rendering.check_size(width, height)
    _check_fps(fps)
    clip = clip_scenario(pick_scenario(robot, scenario), duration, hold)
    rendering.check_camera(load(robot), camera)
    if out.suffix.lower() in rendering.IMAGE_SUFFIXES:  # a still: the last frame
        last: list[np.ndarray] = []

        def keep_last(frame: np.ndarray) -> None:
            last[:] = [frame.copy()]

        film_scenario(clip, keep_last, width, height, fps, camera)
        return rendering.write_media(out, last[-1])
    try:
        with rendering.video_writer(out, width, height, fps) as write:
            film_scenario(clip, write, width, height, fps, camera)
    except RuntimeError as err:
        raise _encoder_error(err, out) from err
    return out


def _encoder_error(err: RuntimeError, out: Path) -> Exception:
    """The video encoder's failure (mediapy's ``Error writing ...``) as an ``OSError``.

    ffmpeg fails on a full disk or a file system gone away; its last line says why.
    Another ``RuntimeError`` comes back unchanged.
    """
    text = str(err)
    if not text.startswith("Error writing"):
        return err
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    reason = lines[-1] if len(lines) > 1 else "ffmpeg failed"
    return OSError(errno.EIO, f"the video encoder (ffmpeg) failed: {reason}", str(out))


def _trails(sim: list[np.ndarray], model: np.ndarray | None, lift: float
            ) -> list[tuple[np.ndarray, np.ndarray, float]]:
    """The model trail (wide, underneath) and the physics trail (narrow, lifted on top)."""
    trails = []
    if model is not None and len(model):
        trails.append((model, rendering.MODEL_RGBA, rendering.MODEL_TRAIL_SCALE))
    trails.append((np.asarray(sim) + np.array([0.0, 0.0, lift]), rendering.SIM_RGBA,
                   rendering.SIM_TRAIL_SCALE))
    return trails


def _film_measurement(scenario: Scenario, on_frame: Callable[[np.ndarray], None],
                      width: int, height: int, fps: int, camera: str) -> int:
    """Film a measurement scenario's ``film`` over ``[0, scenario.duration)``.

    Each run (a new ``data``) starts a new physics trail; its analytic path, if given, is
    drawn whole. The filmed time runs on across runs. Returns the frame count.

    Raises:
        ValueError: the scenario has no film.
    """
    if scenario.film is None:
        raise ValueError(f"{scenario.key} is a measurement without a film")
    filmer: rendering.Filmer | None = None
    data: mujoco.MjData | None = None
    trail: list[np.ndarray] = []
    offset = next_t = 0.0
    count = 0
    progress_bar = bar(int(scenario.duration * fps) + 1, f"wmr render {scenario.key}",
                       unit="frame")
    try:
        for frame in scenario.film(scenario, None):
            if frame.data is not data:
                offset += 0.0 if data is None else data.time
                data, trail = frame.data, []
            if filmer is None:
                cam = rendering.CameraSettings() if camera == "track" else camera
                filmer = rendering.Filmer(frame.model, width, height, cam)
            t = offset + frame.data.time
            if t > scenario.duration - 1e-9:
                break
            if t + 1e-9 < next_t:
                continue
            next_t += 1.0 / fps
            site = frame.data.site_xpos[frame.model.site("base").id]
            trail.append(np.array([site[0], site[1], TRAIL_Z]))
            ref = None
            if frame.reference is not None:
                r = np.asarray(frame.reference)
                ref = np.column_stack([r, np.full(len(r), TRAIL_Z)])
            on_frame(filmer.frame(frame.data, _trails(trail, ref, filmer.trail_width)))
            count += 1
            progress_bar.update()
    finally:
        progress_bar.close()
        if filmer is not None:
            filmer.close()
    return count


def render_clips(folder: Path, robots: list[str] | None = None,
                 on_written: Callable[[Path], None] | None = None) -> list[Path]:
    """Every clip each robot's registry entry lists (:class:`~wmr_mujoco.robots.Clip`).

    The clips of ``renders/`` (``wmr render --all``): a robot added to the registry gets
    its clip without naming it anywhere else. Every robot name and the folder are checked
    before anything is filmed; each clip is written atomically, as by
    :func:`render_to_file`.

    Raises:
        ValueError: an unknown robot, or ``folder`` is not an existing folder.
    """
    from wmr_mujoco.robots import ROBOTS

    folder = Path(folder)
    if not folder.is_dir():
        raise ValueError(f"output folder {str(folder)!r} does not exist; create it first "
                         "(wmr writes only into existing folders)")
    specs = [get_spec(r) for r in robots] if robots else list(ROBOTS.values())
    written = []
    for spec in specs:
        for clip in spec.clips:
            path = render_to_file(spec.name, folder / spec.clip_file(clip), clip.scenario,
                                  clip.width, clip.height, clip.fps, duration=clip.duration)
            written.append(path)
            if on_written is not None:
                on_written(path)
    return written
