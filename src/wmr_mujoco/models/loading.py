"""Loading robots: the checked-in scene files, or a scene built from parameters."""

from __future__ import annotations

import mujoco
from dm_control import mjcf

from wmr_mujoco.models.builders import common
from wmr_mujoco.models.builders.scene import add_scene
from wmr_mujoco.models.params import RobotParams, params_or_default
from wmr_mujoco.robots import get_spec


def build_scene(robot: str, params: RobotParams | None = None) -> mjcf.RootElement:
    """Build the robot from ``params`` (its defaults if None) and add floor and light.

    The result compiles to the same model as the checked-in ``scene.xml``, which
    ``<include>``s the robot file and then declares the same scene elements.

    Raises:
        ValueError: unknown robot, a robot without a builder (a foreign model file), or
            ``params`` of the wrong type.

    """
    spec = get_spec(robot)
    if spec.build is None or spec.params_type is None:
        raise ValueError(f"robot {robot!r} is a model file ({spec.scene_path}) without a "
                         "builder; it takes no parameters")
    try:
        params = params_or_default(params, spec.params_type)
    except ValueError as err:
        raise ValueError(f"params for {robot!r}: {err}") from None
    root = spec.build(params)
    root.model = f"{root.model} scene"
    add_scene(root)
    if spec.scene_extras is not None:
        spec.scene_extras(root, params)
    return root


def load(robot: str, params: RobotParams | None = None) -> mujoco.MjModel:
    """Return the compiled scene of ``robot``.

    Args:
        robot: a name from :data:`wmr_mujoco.robots.ROBOTS`.
        params: None to load the checked-in ``scene.xml`` (a robot without files is built
            from its defaults); otherwise an instance of the robot's parameter
            dataclass, built with dm_control ``mjcf``.

    Raises:
        ValueError: unknown robot name (the message lists the valid ones) or wrong
            parameter type.
        FileNotFoundError: the scene file is missing (the message names the path).

    """
    spec = get_spec(robot)
    if params is not None or not spec.has_files:
        return mujoco.MjModel.from_xml_string(common.to_xml(build_scene(robot, params)))
    path = spec.scene_path
    for needed in (path, spec.robot_path):
        if not needed.is_file():
            raise FileNotFoundError(
                f"model file for {robot!r} not found: {needed} "
                f"(regenerate with `python -m wmr_mujoco.models.export`)"
            )
    return mujoco.MjModel.from_xml_path(str(path))
