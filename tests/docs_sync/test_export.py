import ast
import re
from pathlib import Path

import pytest

import wmr_mujoco
from wmr_mujoco.docs_sync.export import parameter_table, scene_xml
from wmr_mujoco.docs_sync.markers import has_markers
from wmr_mujoco.models.paths import README_PATH
from wmr_mujoco.robots import ROBOTS

TABLED = [name for name, spec in ROBOTS.items()
          if spec.params_type is not None and spec.build is not None and spec.has_files]


@pytest.mark.parametrize("robot", TABLED)
def test_readme_parameter_tables_are_current(robot):
    spec = ROBOTS[robot]
    readme = spec.robot_path.parent / "README.md"
    assert has_markers(readme, f"{robot} parameters"), f"{readme} lacks the table's markers"
    assert parameter_table(spec) in readme.read_text(), (
        "run `make models` to refresh the README tables")


_PACKAGE = Path(wmr_mujoco.__file__).parent
_MARKER = re.compile(r"<!-- (.+?): begin -->")


def _sections() -> list[tuple[Path, str]]:
    """Every marker section of the top-level README, the model READMEs and the docs."""
    root = README_PATH.parent
    files = [README_PATH, *sorted(root.glob("models/*/README.md")),
             *sorted(root.glob("docs/**/*.md"))]
    return [(f, key) for f in files for key in _MARKER.findall(f.read_text())]


def _literal_writers() -> dict[str, set[str]]:
    """Key -> modules that paste generated text (``replace_between`` or ``publish``) and
    hold the key as a string literal."""
    writers: dict[str, set[str]] = {}
    for path in _PACKAGE.rglob("*.py"):
        tree = ast.parse(path.read_text())
        calls = any(isinstance(n, ast.Call)
                    and getattr(n.func, "id", "") in {"replace_between", "publish"}
                    for n in ast.walk(tree))
        if not calls or path.name == "markers.py":
            continue
        for node in ast.walk(tree):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                writers.setdefault(node.value, set()).add(path.stem)
    return writers


def test_each_readme_section_has_exactly_one_writer():
    """Two generators writing one section in different forms make ``make models`` and
    ``make study`` undo each other; a section nobody writes goes stale. The parameter
    tables are :mod:`~wmr_mujoco.docs_sync.export`'s (their keys are built from robot names,
    so no literal of them may appear in another writer)."""
    literal = _literal_writers()
    bad = {}
    for path, key in _sections():
        writers = set(literal.get(key, ()))
        if key in {f"{name} parameters" for name in TABLED}:
            writers.add("export")
        if len(writers) != 1:
            bad[f"{path.relative_to(README_PATH.parent)}: {key}"] = sorted(writers)
    assert not bad, f"sections with no writer or more than one: {bad}"


@pytest.mark.parametrize("robot", list(ROBOTS))
def test_checked_in_scene_files_are_current(robot):
    spec = ROBOTS[robot]
    assert spec.scene_path.read_text() == scene_xml(spec)


def test_class_table_is_current():
    from wmr_mujoco.docs_sync.export import CLASS_TABLE_KEY, CLASS_TABLE_PAGE
    from wmr_mujoco.docs_sync.markers import markers
    from wmr_mujoco.lookup import load
    from wmr_mujoco.models.classify import class_table

    begin, end = markers(CLASS_TABLE_KEY)
    section = CLASS_TABLE_PAGE.read_text().split(begin, 1)[1].split(end, 1)[0].strip()
    assert section == class_table({n: load(n) for n in ROBOTS}), "run `make models`"
