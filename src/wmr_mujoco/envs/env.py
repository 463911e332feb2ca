"""Gymnasium environments of the wheeled robots (``wmr/<Robot>-<Task>-v0``).

Every step holds the robot's natural command (:mod:`wmr_mujoco.drive`) for one control
period (``frame_skip`` MuJoCo timesteps, ``dt = frame_skip · timestep``), through the
environments' own recording-free loop (:mod:`wmr_mujoco.envs.stepping`: the stepping API's
physics, bit for bit, without its history): ``env.unwrapped.episode.state`` is the state
after the last step, while ``env.unwrapped.robot.state`` stays at the last reset. Observation and
action: :mod:`wmr_mujoco.envs.episode` and the task modules
(:mod:`wmr_mujoco.envs.tasks`); ``env.unwrapped.describe()`` lists the observation's
blocks with units.

``info`` of every step: ``reward_terms`` (the reward's terms one by one; the reward is
their sum), ``is_success``, ``failed`` and ``time`` (s). An episode terminates on success
or failure and is truncated at the task's time limit.

Rendering: ``"rgb_array"`` draws offscreen (EGL, else OSMesa: the backend is chosen by
:func:`wmr_mujoco.render.gl_backend.select_backend`) from a camera tracking the robot;
``"human"`` opens MuJoCo's viewer and needs a display.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from typing import Any

import gymnasium as gym
import numpy as np

from wmr_mujoco.envs.episode import Episode
from wmr_mujoco.envs.randomization import Bands

RENDER_MODES = ("rgb_array", "human")
#: The keyword options of :class:`WmrEnv` (``gymnasium.make(id, **options)``).
OPTIONS = ("mode", "randomize", "task_kwargs", "control_period", "render_mode", "width",
           "height")


def has_display() -> bool:
    """Whether a display is set (``DISPLAY`` or ``WAYLAND_DISPLAY``)."""
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def render_modes() -> list[str]:
    """The modes this machine can render: ``"human"`` only with a display."""
    return ["rgb_array", "human"] if has_display() else ["rgb_array"]


class WmrEnv(gym.Env):
    """One robot, one task (see the module docstring and :class:`Episode`).

    Args:
        robot: registry name (``wmr list``) of a robot with actuators.
        task: ``"GoToGoal"``, ``"FollowPath"`` or ``"StayUpright"`` (as the robot offers).
        mode: ``"command"`` (natural command, normalised) or ``"wheels"`` (raw wheel
            commands, normalised).
        randomize: domain randomisation (False; True: the robot's bands; a Bands, or a
            mapping of bands replacing the robot's).
        task_kwargs: the task's options.
        control_period: s per step (None: the robot's profile).
        render_mode: None, ``"rgb_array"`` or ``"human"``.
        width: frame width, pixels.
        height: frame height, pixels.
    """

    metadata: Mapping[str, Any] = {"render_modes": render_modes(), "render_fps": 50}

    def __init__(self, robot: str, task: str, mode: str = "command",
                 randomize: bool | Bands | Mapping = False,
                 task_kwargs: Mapping[str, float] | None = None,
                 control_period: float | None = None, render_mode: str | None = None,
                 width: int = 480, height: int = 360, **unknown: Any) -> None:
        if unknown:  # a typo would otherwise be Python's TypeError, valid names unsaid
            raise TypeError(f"unknown option(s) {sorted(unknown)}; valid: {', '.join(OPTIONS)}")
        if render_mode is not None and render_mode not in RENDER_MODES:
            raise ValueError(f"unknown render_mode {render_mode!r}; valid: None, "
                             f"{', '.join(map(repr, RENDER_MODES))}")
        for name, px in (("width", width), ("height", height)):
            if not isinstance(px, int) or not 16 <= px <= 4096:
                raise ValueError(f"{name}={px!r} pixels; valid: an integer in [16, 4096]")
        if render_mode == "human" and not has_display():
            raise RuntimeError("render_mode='human' needs a display (DISPLAY or "
                               "WAYLAND_DISPLAY is unset); use render_mode='rgb_array'")
        self.episode = Episode(robot, task, mode, randomize, task_kwargs, control_period)
        self.render_mode = render_mode
        self.width, self.height = width, height
        self.dt = self.episode.dt
        self.frame_skip = int(self.episode.robot.nstep)
        self.metadata = {**type(self).metadata, "render_fps": round(1.0 / self.dt)}
        n = self.episode.n_action
        self.action_space = gym.spaces.Box(-1.0, 1.0, (n,), np.float32)
        self.observation_space = gym.spaces.Box(-np.inf, np.inf, (self.episode.size,),
                                                np.float32)
        self._renderer = None
        self._viewer = None
        if render_mode != "human":  # nothing to do around a step: one call less per step
            self.step = self.episode.step  # type: ignore[method-assign]

    @property
    def robot(self) -> Any:
        """The driven robot (:mod:`wmr_mujoco.drive`): model, data, state, command space."""
        return self.episode.robot

    @property
    def task(self) -> Any:
        """The task (goal, path, target speed of the episode)."""
        return self.episode.task

    def describe(self) -> str:
        """The observation's blocks with their units."""
        return self.episode.describe()

    def reset(self, *, seed: int | None = None, options: Mapping[str, Any] | None = None
              ) -> tuple[np.ndarray, dict]:
        """Start an episode (seeded by ``seed``: task draw, randomisation, wheel phases).

        Raises:
            ValueError: ``options`` given (the environment takes none at reset; the
                task's options are ``task_kwargs`` of ``gymnasium.make``).
        """
        if options:
            raise ValueError(f"reset() takes no options, got {sorted(options)}; set the "
                             "task's options with gymnasium.make(id, task_kwargs={...})")
        super().reset(seed=seed)
        obs = self.episode.reset(self.np_random)
        info = {"randomization": dict(self.episode.factors)}
        if self.render_mode == "human":
            self.render()
        return obs, info

    def step(self, action: Any) -> tuple[np.ndarray, float, bool, bool, dict]:
        """One control period (see :meth:`Episode.step`)."""
        out = self.episode.step(action)
        if self.render_mode == "human":
            self.render()
        return out

    def render(self) -> np.ndarray | None:
        """A frame (``"rgb_array"``), or an update of the viewer (``"human"``)."""
        if self.render_mode is None:
            gym.logger.warn("render() called without a render_mode; pass render_mode="
                            "'rgb_array' to gymnasium.make")
            return None
        if self.render_mode == "human":
            return self._render_human()
        return self._render_rgb()

    def _render_rgb(self) -> np.ndarray:
        from wmr_mujoco.envs.drawing import draw_task
        from wmr_mujoco.render.gl_backend import select_backend

        if self._renderer is None:
            select_backend()
            import mujoco

            from wmr_mujoco.render.rendering import CameraSettings, tracking_camera

            self._renderer = mujoco.Renderer(self.robot.model, self.height, self.width)
            self._camera = tracking_camera(self.robot.model, CameraSettings(distance=6.0))
        self._renderer.update_scene(self.robot.data, self._camera)
        draw_task(self._renderer.scene, self.task)
        return self._renderer.render()

    def _render_human(self) -> None:
        import mujoco.viewer

        if self._viewer is None:
            self._viewer = mujoco.viewer.launch_passive(self.robot.model, self.robot.data)
        self._viewer.sync()

    def close(self) -> None:
        """Free the renderer and the viewer."""
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None
        if self._viewer is not None:
            self._viewer.close()
            self._viewer = None
