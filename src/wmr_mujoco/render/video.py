"""Videos of validation scenarios with the analytic trajectory drawn beside the physics.

Call :func:`wmr_mujoco.render.gl_backend.select_backend` before MuJoCo is first imported (the
``wmr render`` command does) to get the EGL → OSMesa fallback.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco.models.loading import load
from wmr_mujoco.render import rendering
from wmr_mujoco.robots import get_spec
from wmr_mujoco.sim.stepping import SimulationDivergedError, check_healthy
from wmr_mujoco.validation.adapters import Adapter
from wmr_mujoco.validation.runner import run_scenario
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind

#: Trail height above the floor, m.
TRAIL_Z = 0.003


def pick_scenario(robot: str, name: str | None = None) -> Scenario:
    """The named scenario of ``robot`` (default: its render scenario, else first kinematic).

    Raises:
        ValueError: unknown robot, a robot without kinematic scenarios, or no such
            scenario (the message lists the valid ones).
    """
    spec = get_spec(robot)
    name = name or spec.render_scenario
    if name is not None:
        return spec.scenario(name)
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
    if scenario.kind is ScenarioKind.MEASUREMENT:
        return render_free_run(scenario, width, height, fps, camera)
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


def render_free_run(scenario: Scenario, width: int = 640, height: int = 480, fps: int = 30,
                    camera: str = "track") -> np.ndarray:
    """Frames of a measurement scenario's free run: its ``start`` state, no control.

    Only the simulated path of the base is drawn (green): a measurement has no analytic
    trajectory to draw beside it. The run is the scenario's own (same start, same
    model), for ``scenario.duration`` seconds.

    Raises:
        ValueError: the scenario has no start state (nothing single to film); the message
            lists the robot's scenarios that can be rendered.
        SimulationDivergedError: the run diverged.
    """
    if scenario.start is None:
        spec = get_spec(scenario.robot)
        ok = [s.name for s in spec.scenarios
              if s.kind is not ScenarioKind.MEASUREMENT or s.start is not None]
        raise ValueError(f"{scenario.key} is a measurement without a single run to film; "
                         f"scenarios that can be rendered: {', '.join(map(repr, ok))}")
    model = load(scenario.robot)
    data = mujoco.MjData(model)
    scenario.start(model, data, None)
    data.ctrl[:] = 0.0
    cam = rendering.CameraSettings() if camera == "track" else camera
    frames: list[np.ndarray] = []
    trail: list[np.ndarray] = []
    base = model.site("base").id
    nstep = round(scenario.duration / model.opt.timestep)
    every = 1.0 / fps
    with rendering.Filmer(model, width, height, cam) as filmer:
        next_t = data.time
        for _ in range(nstep):
            if data.time + 1e-9 >= next_t:
                next_t += every
                site = data.site_xpos[base]
                trail.append(np.array([site[0], site[1], TRAIL_Z]))
                frames.append(filmer.frame(data, [(np.asarray(trail), rendering.SIM_RGBA)]))
            mujoco.mj_step(model, data)
            check_healthy(model, data)
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
