"""The ``mecanum4`` robot's registry entry, loading and checked-in files.

``python -m wmr_mujoco.mecanum_model [--picture]`` writes ``models/mecanum4/mecanum4.xml``,
``scene.xml``, the README's parameter table (and the picture) from the builder's defaults (what
``python -m wmr_mujoco.export`` does for the registered robots; once :data:`SPEC` is in
the registry, that command covers this robot too).
"""

from __future__ import annotations

from pathlib import Path

import mujoco

from wmr_mujoco.atomic import write_text_atomic
from wmr_mujoco.builders import common, mecanum4
from wmr_mujoco.builders.scene import add_scene
from wmr_mujoco.export import scene_xml, update_readme
from wmr_mujoco.params_mecanum import MecanumParams
from wmr_mujoco.registry import RobotSpec

#: The registry entry (integration: add it to ``wmr_mujoco.registry.ROBOTS``).
SPEC = RobotSpec("mecanum4", "four mecanum wheels (O layout on the floor), one row of "
                 "passive ideal-profile rollers at 45 degrees on free hinges each",
                 "mecanum4", "mecanum4.xml", "scene.xml", MecanumParams, mecanum4.build)


def load_mecanum(params: MecanumParams | None = None) -> mujoco.MjModel:
    """Compiled scene: the checked-in ``scene.xml`` (None) or one built from ``params``.

    Raises:
        ValueError: ``params`` is not a :class:`MecanumParams`.
        FileNotFoundError: the checked-in scene is missing (names the path).
    """
    if params is None:
        if not SPEC.scene_path.is_file():
            raise FileNotFoundError(f"model file for 'mecanum4' not found: {SPEC.scene_path} "
                                    "(regenerate with `python -m wmr_mujoco.mecanum_model`)")
        return mujoco.MjModel.from_xml_path(str(SPEC.scene_path))
    if not isinstance(params, MecanumParams):
        raise ValueError(f"params for 'mecanum4' must be a MecanumParams, "
                         f"got {type(params).__name__}")
    root = mecanum4.build(params)
    root.model = f"{root.model} scene"
    add_scene(root)
    return mujoco.MjModel.from_xml_string(common.to_xml(root))


def write_files() -> list[Path]:
    """Write the robot file, the scene file and the README parameter table."""
    write_text_atomic(SPEC.robot_path, common.to_xml(SPEC.build(MecanumParams())))
    write_text_atomic(SPEC.scene_path, scene_xml(SPEC))
    written = [SPEC.robot_path, SPEC.scene_path]
    readme = update_readme(SPEC)
    if readme is not None:
        written.append(readme)
    return written


def write_picture(width: int = 640, height: int = 400) -> Path:
    """Render the robot at rest to ``models/mecanum4/mecanum4.png`` (as ``wmr_mujoco.pictures``)."""
    from wmr_mujoco.gl_backend import select_backend

    select_backend()
    from wmr_mujoco.rendering import CameraSettings, Filmer, write_media

    model = load_mecanum()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    with Filmer(model, width, height, CameraSettings(shadows=True, reflections=True,
                                                      elevation=-35)) as f:
        image = f.frame(data)
    return write_media(SPEC.robot_path.with_suffix(".png"), image)


if __name__ == "__main__":
    import sys

    for p in write_files():
        print(f"wrote {p}")
    if "--picture" in sys.argv[1:]:
        print(f"wrote {write_picture()}")
