"""Model folders of the caster robots: ``python -m wmr_mujoco.wheeled_export``.

Writes, for diffdrive, single_steer and double_steer, ``models/<robot>/<robot>.xml`` and
``scene.xml`` from the builders' defaults (with :func:`wmr_mujoco.export.scene_xml`, the
scene writer every robot uses), and pastes the generated tables between the README
markers: parameters (:func:`wmr_mujoco.export.parameter_table`), the Campion class table
of all robots (:mod:`wmr_mujoco.analytic.campion`), the validation figures
(:mod:`wmr_mujoco.wheeled_scenarios`) and the caster drag (:mod:`wmr_mujoco.caster_drag`).
``--pictures`` also renders each robot's picture. The registry's own exporter does not
know these robots until they are merged into it; then this module reduces to the tables.
"""

from __future__ import annotations

import sys
from pathlib import Path

from wmr_mujoco.atomic import write_text_atomic
from wmr_mujoco.builders import common
from wmr_mujoco.export import parameter_table, scene_xml
from wmr_mujoco.markers import has_markers, replace_between
from wmr_mujoco.wheeled_registry import SPECS

#: Robots in the class table: (name, source) with source "registry" or "wheeled".
CLASS_TABLE_ROBOTS = (("omni3", "registry"), ("bicycle", "registry"), ("tricycle", "registry"),
                      ("diffdrive", "wheeled"), ("single_steer", "wheeled"),
                      ("double_steer", "wheeled"))


def class_table() -> str:
    """Markdown table: robot, wheels found, δm, δs, δM, class (computed from each model)."""
    from wmr_mujoco import loading
    from wmr_mujoco import wheeled_scenarios as ws
    from wmr_mujoco.analytic import campion

    rows = ["| robot | wheels found | δm | δs | δM | class |", "|---|---|---|---|---|---|"]
    for name, source in CLASS_TABLE_ROBOTS:
        model = loading.load(name) if source == "registry" else ws.load(name)
        c = campion.classify(model)
        kinds = ", ".join(f"{n} {k}" for k, n in c.wheel_counts().items())
        cls = f"({c.delta_m},{c.delta_s})" if c.robot_class else f"none: {c.reason}"
        rows.append(f"| {name} | {kinds} | {c.delta_m} | {c.delta_s} | {c.manoeuvrability} | "
                    f"{cls} |")
    return "\n".join(rows)


def _paste(readme: Path, key: str, body: str, written: list[Path]) -> None:
    if has_markers(readme, key):
        replace_between(readme, key, body)
        written.append(readme)


def export_models() -> list[Path]:
    """Write every caster robot's robot and scene files and its parameter table."""
    written = []
    for spec in SPECS.values():
        spec.robot_path.parent.mkdir(parents=True, exist_ok=True)
        write_text_atomic(spec.robot_path, common.to_xml(spec.build(spec.params_type())))
        write_text_atomic(spec.scene_path, scene_xml(spec))
        written += [spec.robot_path, spec.scene_path]
        _paste(spec.robot_path.parent / "README.md", f"{spec.name} parameters",
               parameter_table(spec), written)
    return written


def export_tables() -> list[Path]:
    """Paste the class table, validation figures and caster drag into the READMEs."""
    from wmr_mujoco import caster_drag
    from wmr_mujoco import wheeled_scenarios as ws

    written: list[Path] = []
    classes = class_table()
    drag = caster_drag.drag_table()
    for spec in SPECS.values():
        readme = spec.robot_path.parent / "README.md"
        _paste(readme, "campion classes", classes, written)
        _paste(readme, f"{spec.name} validation",
               ws.table([ws.measure(s) for s in ws.scenarios_for(spec.name)]), written)
        _paste(readme, "caster drag", drag, written)
    return written


def write_pictures(width: int = 640, height: int = 400) -> list[Path]:
    """Render each caster robot at rest, steering turned, to ``models/<robot>/<robot>.png``."""
    from wmr_mujoco.gl_backend import select_backend

    select_backend()
    import mujoco

    from wmr_mujoco import wheeled_scenarios as ws
    from wmr_mujoco.rendering import CameraSettings, Filmer, write_media

    written = []
    for spec in SPECS.values():
        model = ws.load(spec.name)
        data = mujoco.MjData(model)
        for j in range(model.njnt):
            name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, j) or ""
            if name.endswith("_steer"):
                data.qpos[model.jnt_qposadr[j]] = 0.35
        mujoco.mj_forward(model, data)
        with Filmer(model, width, height, CameraSettings(shadows=True, reflections=True,
                                                          elevation=-35)) as f:
            image = f.frame(data)
        written.append(write_media(spec.robot_path.with_suffix(".png"), image))
    return written


if __name__ == "__main__":
    paths = export_models() + export_tables()
    if "--pictures" in sys.argv[1:]:
        paths += write_pictures()
    for p in paths:
        print(f"wrote {p}")
