"""Write the checked-in MJCF files from the builders' default parameters.

Run ``python -m wmr_mujoco.docs_sync.export`` after changing a builder or a default parameter;
``tests/models/test_loading.py`` fails until the files agree with the builders again.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

from dm_control import mjcf
from lxml import etree

from wmr_mujoco.atomic import write_text_atomic
from wmr_mujoco.docs_sync.markers import has_markers, replace_between
from wmr_mujoco.info import used_params
from wmr_mujoco.models.builders import common
from wmr_mujoco.models.builders.scene import add_scene
from wmr_mujoco.models.params import RobotParams, WheelParams
from wmr_mujoco.models.paths import DOCS_DIR
from wmr_mujoco.robots import ROBOTS, RobotSpec


def scene_xml(spec: RobotSpec, params: RobotParams | None = None) -> str:
    """The ``scene.xml`` text: an include of the robot file, then the scene elements.

    The scene elements are those of ``params`` (default: the robot's default parameters).
    """
    scene = mjcf.RootElement(model=f"{spec.name} scene")
    add_scene(scene)
    if spec.scene_extras is not None and spec.params_type is not None:
        spec.scene_extras(scene, params if params is not None else spec.params_type())
    tree = etree.fromstring(common.to_xml(scene).encode())
    for el in list(tree):
        if el.tag in ("compiler", "default") or (len(el) == 0 and not el.attrib):
            tree.remove(el)
    tree.insert(0, etree.Element("include", file=spec.robot_file))
    etree.indent(tree, space="  ")
    return etree.tostring(tree, encoding="unicode") + "\n"


def parameter_table(spec: RobotSpec) -> str:
    """Markdown table of the robot's default parameters and derived wheel inertias."""
    params = spec.params_type()
    rows = ["| parameter | value |", "|---|---|"]
    rows += [f"| `{k}` | {v} |" for k, v in used_params(params).items()]
    for f in dataclasses.fields(params):
        value = getattr(params, f.name)
        if isinstance(value, WheelParams):
            rows.append(f"| `{f.name}` axial inertia m R²/2 | {value.axial_inertia:.6g} kg·m² |")
            rows.append(f"| `{f.name}` diametral inertia | {value.diametral_inertia:.6g} kg·m² |")
    rows.append(f"| total mass | {params.total_mass:.6g} kg |")
    return "\n".join(rows)


def update_readme(spec: RobotSpec) -> Path | None:
    """Replace the text between the README's table markers with :func:`parameter_table`."""
    readme = spec.robot_path.parent / "README.md"
    key = f"{spec.name} parameters"
    if not has_markers(readme, key):
        return None
    replace_between(readme, key, parameter_table(spec))
    return readme


#: Marker key of the class table (:func:`update_class_table`) and the page that holds it.
CLASS_TABLE_KEY = "campion classes"
CLASS_TABLE_PAGE = DOCS_DIR / "campion-classes.md"


def update_class_table(readme: Path = CLASS_TABLE_PAGE) -> Path | None:
    """Paste the Campion class of every registered robot, computed from its model."""
    from wmr_mujoco.models.classify import class_table
    from wmr_mujoco.models.loading import load

    if not has_markers(readme, CLASS_TABLE_KEY):
        return None
    replace_between(readme, CLASS_TABLE_KEY, class_table({n: load(s) for n, s in ROBOTS.items()}))
    return readme


def export_all() -> list[Path]:
    """Write every robot's files and README parameter table, and the Campion class table."""
    written = []
    for spec in ROBOTS.values():
        if spec.build is None or spec.params_type is None or not spec.has_files:
            continue
        write_text_atomic(spec.robot_path, common.to_xml(spec.build(spec.params_type())))
        write_text_atomic(spec.scene_path, scene_xml(spec))
        written += [spec.robot_path, spec.scene_path]
        readme = update_readme(spec)
        if readme is not None:
            written.append(readme)
    readme = update_class_table()
    if readme is not None:
        written.append(readme)
    return written


if __name__ == "__main__":
    for p in export_all():
        print(f"wrote {p}")
