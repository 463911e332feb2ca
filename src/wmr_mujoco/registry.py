"""The one registry of robots: name, description, files, parameters and builder."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from dm_control import mjcf

from wmr_mujoco.builders import bicycle, disc, omni3, tricycle
from wmr_mujoco.params import BicycleParams, DiscParams, OmniParams, TricycleParams
from wmr_mujoco.paths import MODELS_DIR


@dataclass(frozen=True)
class RobotSpec:
    """Everything the package knows about one robot.

    Attributes:
        name: registry key, also the model name.
        description: one line for ``wmr list``.
        folder: model folder name under :data:`~wmr_mujoco.paths.MODELS_DIR`.
        robot_file: robot-only MJCF file in that folder.
        scene_file: MJCF file that includes the robot and adds floor and light.
        params_type: frozen dataclass of the robot's physical parameters.
        build: builder ``params -> mjcf.RootElement`` of the robot alone.

    """

    name: str
    description: str
    folder: str
    robot_file: str
    scene_file: str
    params_type: type
    build: Callable[[Any], mjcf.RootElement]

    @property
    def robot_path(self) -> Path:
        """Absolute path of the robot-only MJCF file."""
        return MODELS_DIR / self.folder / self.robot_file

    @property
    def scene_path(self) -> Path:
        """Absolute path of the scene MJCF file."""
        return MODELS_DIR / self.folder / self.scene_file


ROBOTS: dict[str, RobotSpec] = {
    spec.name: spec
    for spec in (
        RobotSpec("disc", "single steerable thin disc on a vertical mount; inputs "
                  "wheel rate and steering rate", "disc", "disc.xml", "scene.xml",
                  DiscParams, disc.build),
        RobotSpec("disc_free", "free thin disc on a free joint, no actuators; keyframes "
                  "for rolling, spinning and leaning starts", "disc", "disc_free.xml",
                  "scene_free.xml", DiscParams, disc.build_free),
        RobotSpec("bicycle", "planar bicycle held upright: driven rear wheel, steered "
                  "front fork", "bicycle", "bicycle.xml", "scene.xml", BicycleParams,
                  bicycle.build),
        RobotSpec("tricycle", "tricycle on a free joint: steered front wheel, left rear "
                  "wheel driven, right rear wheel free (or an open differential)",
                  "tricycle", "tricycle.xml", "scene.xml", TricycleParams,
                  tricycle.build),
        RobotSpec("omni3", "three omni wheels at 120 degrees, each with two staggered rows "
                  "of passive barrel rollers on free hinges", "omni3", "omni3.xml",
                  "scene.xml", OmniParams, omni3.build),
    )
}


def get_spec(robot: str) -> RobotSpec:
    """Look a robot up by name.

    Raises:
        ValueError: the name is not registered; the message lists the valid names.

    """
    try:
        return ROBOTS[robot]
    except (KeyError, TypeError):
        raise ValueError(
            f"unknown robot {robot!r}; valid robots are: {', '.join(ROBOTS)}"
        ) from None
