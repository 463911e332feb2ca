"""``wmr export ROBOT --set FIELD=VALUE ... --out DIR``: a robot with your dimensions.

Writes a Menagerie-style folder: the robot file, ``scene.xml`` (the robot included, with
floor and light) and a README with the parameter table, through the robot's own builder
and parameter dataclass (the same writers as :mod:`wmr_mujoco.docs_sync.export`). Every
``--set`` is checked before anything is written: an unknown field names the valid ones,
a bad value the field's type and the dataclass's own range check.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from pathlib import Path

from wmr_mujoco.atomic import write_text_atomic
from wmr_mujoco.audit.errors import AuditInputError
from wmr_mujoco.docs_sync.export import scene_xml
from wmr_mujoco.info import used_params
from wmr_mujoco.models.builders import common
from wmr_mujoco.models.params import RobotParams
from wmr_mujoco.robots import ROBOTS, RobotSpec


def _parse(field: str, text: str, current: object) -> object:
    if isinstance(current, bool):
        if text.lower() in ("true", "1", "yes"):
            return True
        if text.lower() in ("false", "0", "no"):
            return False
        raise AuditInputError(f"--set {field}={text}: {field} is true or false")
    if isinstance(current, (int, float)):
        try:
            return type(current)(float(text)) if isinstance(current, float) else int(text)
        except ValueError:
            raise AuditInputError(f"--set {field}={text}: {field} is a number "
                                  f"(now {current})") from None
    if isinstance(current, str):
        return text
    raise AuditInputError(f"--set {field}: a {type(current).__name__} cannot be set from the "
                          "command line")


def _replace(params: object, path: list[str], value: object) -> object:
    if len(path) == 1:
        return dataclasses.replace(params, **{path[0]: value})
    inner = _replace(getattr(params, path[0]), path[1:], value)
    return dataclasses.replace(params, **{path[0]: inner})


def params_with(spec: RobotSpec, settings: Sequence[str]) -> RobotParams:
    """The robot's default parameters with ``FIELD=VALUE`` settings applied.

    Raises:
        AuditInputError: a setting without ``=``, an unknown field (the valid ones are
            listed), or a value of the wrong type or outside the field's range.
    """
    if spec.params_type is None:
        raise AuditInputError(f"{spec.name} has no parameters to set")
    params = spec.params_type()
    fields = used_params(params)
    for item in settings:
        field, sep, text = item.partition("=")
        if not sep:
            raise AuditInputError(f"--set {item!r}: expected FIELD=VALUE")
        if field not in fields:
            raise AuditInputError(f"--set {field}: no such field of {spec.name}; valid: "
                                  f"{', '.join(fields)}")
        try:
            params = _replace(params, field.split("."), _parse(field, text, fields[field]))
        except (ValueError, TypeError) as err:
            if isinstance(err, AuditInputError):
                raise
            raise AuditInputError(f"--set {field}={text}: {err}") from None
    return params


def readme(spec: RobotSpec, params: RobotParams, settings: Sequence[str]) -> str:
    """The folder's README: what it is, how it was made, the parameter table."""
    rows = ["| parameter | value |", "|---|---|"]
    rows += [f"| `{k}` | {v} |" for k, v in used_params(params).items()]
    rows.append(f"| total mass | {params.total_mass:.6g} kg |")
    made = " ".join(f"--set {s}" for s in settings)
    return "\n".join([
        f"# {spec.name} (custom dimensions)", "", spec.description, "",
        f"Written by `wmr export {spec.name} {made}` through the package's builder; "
        f"`{spec.robot_file}` is the robot, `scene.xml` adds floor and light. The audit "
        "of this model is in `audit/`.", "", "## Parameters (SI units, radians)", "",
        *rows, ""])


def export_robot(robot: str, settings: Sequence[str], out: Path) -> Path:
    """Write the folder (see the module docstring) and return its ``scene.xml``.

    Raises:
        AuditInputError: unknown robot, a robot without a builder, or a bad setting.
    """
    if robot not in ROBOTS:
        raise AuditInputError(f"unknown robot {robot!r}; valid: {', '.join(ROBOTS)}")
    spec = ROBOTS[robot]
    if spec.build is None or not spec.robot_file:
        raise AuditInputError(f"{robot} has no builder to export")
    params = params_with(spec, settings)
    xml = common.to_xml(spec.build(params))
    out = Path(out)
    out.mkdir(exist_ok=True)
    write_text_atomic(out / spec.robot_file, xml)
    write_text_atomic(out / "scene.xml", scene_xml(spec, params))
    write_text_atomic(out / "README.md", readme(spec, params, settings))
    return out / "scene.xml"
