"""Videos of validation scenarios with the analytic trajectory drawn beside the physics.

Kinematic and dynamic scenarios are filmed through the runner; a measurement scenario
through its own ``film`` (the runs it measures, step by step), with the physics trail
and, where the scenario gives one, its analytic path.

Call :func:`wmr_mujoco.render.gl_backend.select_backend` before MuJoCo is first imported (the
``wmr render`` command does) to get the EGL → OSMesa fallback.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco.render import rendering
from wmr_mujoco.robots import get_spec
from wmr_mujoco.sim.stepping import SimulationDivergedError
from wmr_mujoco.validation.adapters import Adapter
from wmr_mujoco.validation.runner import run_scenario
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind

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


def render_scenario(scenario: Scenario, width: int = 640, height: int = 480, fps: int = 30,
                    camera: str = "track", duration: float | None = None) -> np.ndarray:
    """Simulate ``scenario`` and return its frames ``(n, height, width, 3)``.

    The simulated path of the base is drawn in green and the analytic model's in red.

    Raises:
        ValueError: bad size, fps, duration or camera.
        SimulationDivergedError: the run diverged.
    """
    rendering.check_size(width, height)
    if not isinstance(fps, int) or not 1 <= fps <= 120:
        raise ValueError(f"fps = {fps!r}; valid range is integers [1, 120]")
    if duration is not None:
        if not 0 < duration <= scenario.duration:
            raise ValueError(f"duration = {duration!r} s; valid range is (0, "
                             f"{scenario.duration:g}] for {scenario.key}")
        scenario = dataclasses.replace(scenario, duration=duration)
    frames: list[np.ndarray] = []
    sim_trail: list[np.ndarray] = []
    model_trail: list[np.ndarray] = []
    state: dict[str, object] = {}

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
        frames.append(state["filmer"].frame(  # type: ignore[union-attr]
            data, [(np.asarray(sim_trail), rendering.SIM_RGBA),
                   (np.asarray(model_trail), rendering.MODEL_RGBA)]))

    if scenario.kind is ScenarioKind.MEASUREMENT:
        _film_measurement(scenario, width, height, fps, camera, frames)
        return np.asarray(frames)
    try:
        result = run_scenario(scenario, observer=observe)
    finally:
        if "filmer" in state:
            state["filmer"].close()  # type: ignore[union-attr]
    if result.error is not None:
        if result.error.startswith("ValueError: "):
            raise ValueError(result.error.removeprefix("ValueError: "))
        raise SimulationDivergedError(f"{scenario.key}: {result.error}")
    return np.asarray(frames)


def render_to_file(robot: str, out: Path, scenario: str | None = None, width: int = 640,
                   height: int = 480, fps: int = 30, camera: str = "track",
                   duration: float | None = None) -> Path:
    """Render a scenario of ``robot`` to ``out`` (.mp4 or .gif), atomically.

    The output path is checked before anything is simulated; a failure leaves no file.
    """
    out = rendering.check_output_path(Path(out), rendering.VIDEO_SUFFIXES)
    rendering.check_size(width, height)
    frames = render_scenario(pick_scenario(robot, scenario), width, height, fps, camera,
                             duration)
    return rendering.write_media(out, frames, fps=fps)


def _film_measurement(scenario: Scenario, width: int, height: int, fps: int, camera: str,
                      frames: list[np.ndarray]) -> None:
    """Append frames of a measurement scenario's ``film`` over ``[0, scenario.duration)``.

    Each run (a new ``data``) starts a new physics trail; its analytic path, if given, is
    drawn whole. The filmed time runs on across runs.
    """
    assert scenario.film is not None  # pick_scenario checked
    filmer: rendering.Filmer | None = None
    data: mujoco.MjData | None = None
    trail: list[np.ndarray] = []
    offset = next_t = 0.0
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
            trails = [(np.asarray(trail), rendering.SIM_RGBA)]
            if frame.reference is not None:
                ref = np.asarray(frame.reference)
                trails.append((np.column_stack([ref, np.full(len(ref), TRAIL_Z)]),
                               rendering.MODEL_RGBA))
            frames.append(filmer.frame(frame.data, trails))
    finally:
        if filmer is not None:
            filmer.close()
