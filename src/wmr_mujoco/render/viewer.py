"""MuJoCo's interactive viewer running a scenario in real time (needs a display)."""

from __future__ import annotations

import time

import mujoco
import mujoco.viewer

from wmr_mujoco.lookup import load
from wmr_mujoco.models.actuation import set_actuation_mode
from wmr_mujoco.render.video import pick_scenario
from wmr_mujoco.robots import get_spec
from wmr_mujoco.validation.runner import make_adapter
from wmr_mujoco.validation.scenarios import Scenario, ScenarioKind


def view(robot: str, scenario: str | None = None) -> None:
    """Open the viewer on ``robot`` and drive it through a scenario's inputs, looping.

    A measurement scenario plays its ``film`` (the runs it measures) instead.
    """
    s = pick_scenario(robot, scenario)
    if s.kind is ScenarioKind.MEASUREMENT:
        _play_film(s)
        return
    model = load(robot)
    adapter = make_adapter(get_spec(s.robot), s, model)
    if adapter.mode is not None:
        set_actuation_mode(model, adapter.mode)
    data = mujoco.MjData(model)
    with mujoco.viewer.launch_passive(model, data) as handle:
        start = time.perf_counter()
        while handle.is_running():
            t = data.time - s.settle
            if t > s.duration:
                mujoco.mj_resetData(model, data)
                start = time.perf_counter()
                continue
            u = s.input_at(max(t, 0.0)) if t >= 0 else 0 * s.input_at(0.0)
            data.ctrl[:] = adapter.controls(u, adapter.sim_state(model, data))
            mujoco.mj_step(model, data)
            handle.sync()
            lag = data.time - (time.perf_counter() - start)
            if lag > 0:
                time.sleep(lag)


def _play_film(s: Scenario) -> None:
    """Play a measurement scenario's film in real time, looping, until the viewer closes.

    The viewer holds one model and data; each frame's state is copied into them.
    """
    assert s.film is not None  # pick_scenario checked
    first = next(iter(s.film(s, None)))
    model, data = first.model, mujoco.MjData(first.model)
    with mujoco.viewer.launch_passive(model, data) as handle:
        while handle.is_running():
            start, offset, last = time.perf_counter(), 0.0, None
            for frame in s.film(s, None):
                if not handle.is_running():
                    return
                if last is not None and frame.data is not last:
                    offset += last.time
                last = frame.data
                data.qpos[:], data.qvel[:] = frame.data.qpos, frame.data.qvel
                data.time = offset + frame.data.time
                mujoco.mj_forward(model, data)
                handle.sync()
                lag = data.time - (time.perf_counter() - start)
                if lag > 0:
                    time.sleep(lag)
