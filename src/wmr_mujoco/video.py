"""Videos of validation scenarios with the analytic trajectory drawn beside the physics.

Call :func:`wmr_mujoco.gl_backend.select_backend` before MuJoCo is first imported (the
``wmr render`` command does) to get the EGL → OSMesa fallback.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import mujoco
import numpy as np

from wmr_mujoco import rendering
from wmr_mujoco.adapters import Adapter
from wmr_mujoco.registry import get_spec
from wmr_mujoco.scenarios import Scenario, scenarios_for
from wmr_mujoco.simulation import SimulationDivergedError
from wmr_mujoco.validation import run_scenario

#: Trail height above the floor, m.
TRAIL_Z = 0.003


def pick_scenario(robot: str, name: str | None = None) -> Scenario:
    """The named scenario of ``robot`` (default: its first kinematic one).

    Raises:
        ValueError: unknown robot, or no such scenario (the message lists the valid ones).
    """
    get_spec(robot)
    options = [s for s in scenarios_for([robot]) if s.kind == "kinematic"]
    if name is None:
        return options[0]
    for s in scenarios_for([robot]):
        if s.name == name:
            return s
    raise ValueError(f"no scenario {name!r} for {robot!r}; valid scenarios: "
                     f"{', '.join(repr(s.name) for s in scenarios_for([robot]))}")


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
        if len(x) >= 2 and adapter.state_names[:2] == ("x", "y"):
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
