"""Write the checked-in MJCF files from the builders' default parameters.

Run ``python -m wmr_mujoco.export`` after changing a builder or a default parameter;
``tests/test_loading.py`` fails until the files agree with the builders again.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from dm_control import mjcf
from lxml import etree

from wmr_mujoco.builders import common
from wmr_mujoco.builders.scene import add_scene
from wmr_mujoco.registry import ROBOTS, RobotSpec


def write_atomic(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` through a temporary file and an atomic rename."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def scene_xml(spec: RobotSpec) -> str:
    """The ``scene.xml`` text: an include of the robot file, then the scene elements."""
    scene = mjcf.RootElement(model=f"{spec.name} scene")
    add_scene(scene)
    tree = etree.fromstring(common.to_xml(scene).encode())
    for el in list(tree):
        if el.tag in ("compiler", "default") or (len(el) == 0 and not el.attrib):
            tree.remove(el)
    tree.insert(0, etree.Element("include", file=spec.robot_file))
    etree.indent(tree, space="  ")
    return etree.tostring(tree, encoding="unicode") + "\n"


def export_all() -> list[Path]:
    """Write every robot's robot file and scene file; return the paths written."""
    written = []
    for spec in ROBOTS.values():
        write_atomic(spec.robot_path, common.to_xml(spec.build(spec.params_type())))
        write_atomic(spec.scene_path, scene_xml(spec))
        written += [spec.robot_path, spec.scene_path]
    return written


if __name__ == "__main__":
    for p in export_all():
        print(f"wrote {p}")
