"""The package's dependencies run one way, and every module stays small.

Layers, bottom to top; a module may import its own layer and the layers below it, never
one above. The imports are read from the source with :mod:`ast`: module-level imports and
imports inside functions alike (a deferred import is still a dependency).

1. ``core``: the package root, :mod:`~wmr_mujoco.atomic`, :mod:`~wmr_mujoco.choices`,
   :mod:`~wmr_mujoco.progress`, the OpenGL helpers (``gl_env``,
   :mod:`~wmr_mujoco.render.gl_backend`: the backend is chosen before MuJoCo loads);
2. ``parameters``: the generic parameter dataclasses (``models.params``: the
   :class:`RobotParams` protocol, the field checks, the parts several robots share), the
   primitive solids' mass properties (``models.solids``) and the file locations
   (``models.paths``). Analytic models read parameters;
3. ``analytic``: the textbook models several robots use. They know nothing of MJCF;
4. ``models``: the shared MJCF pieces (``models.builders.common``, ``scene``, ``caster``),
   scene loading, actuation, colliders, classification. The classifier uses the rank
   theory, hence above ``analytic``; an analytic model that imported a builder would run
   back up;
5. ``sim``: stepping, timing, contact closed forms;
6. ``validation``: scenarios, adapters, judges, the runner and the report. It receives a
   :class:`~wmr_mujoco.validation.spec.RobotSpec`, never a name to look up;
7. ``loop``: closing the loop on a spec: the steppable robot (``build_robot``, its
   MuJoCo, kinematic and dynamic backends), the controllers and paths, and the
   closed-loop tasks with their judged scenario families, which the registry adds to its
   entries (hence below ``robots``; by name, ``wmr_mujoco.make`` is ``application``);
8. ``robots``: the registry (``ROBOTS``, ``get_spec``) and one folder per robot
   (``robots/<robot>/``: its ``params``, ``builder``, its own analytic model, adapters,
   judges, scenarios and the entry ``SPEC`` in ``__init__``), family code in family folders
   (``robots/roller_wheels/``, ``robots/steered/``). Nothing below imports a robot folder;
9. ``application``: everything else (``api``, ``cli``, ``info``, ``demo``, ``bench``,
   ``render``, ``docs_sync`` and the application packages ``drive``, ``control``,
   ``envs``, ``suite``, ``batch``, ``audit``).

No two subpackages import each other in a cycle (a subpackage that spans two layers,
``models`` or ``render``, counts as one node per layer).
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
PACKAGE = SRC / "wmr_mujoco"

#: Longest module allowed, lines: one concept per module (mink's largest is under 300).
MAX_LINES = 400

#: (layer, module-name prefixes), bottom to top; the longest matching prefix wins and a
#: module no prefix matches is ``application``.
LAYERS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("core", ("wmr_mujoco", "wmr_mujoco.atomic", "wmr_mujoco.choices", "wmr_mujoco.gl_env",
              "wmr_mujoco.progress", "wmr_mujoco.render.gl_backend")),
    ("parameters", ("wmr_mujoco.models.params", "wmr_mujoco.models.solids",
                    "wmr_mujoco.models.paths")),
    ("analytic", ("wmr_mujoco.analytic",)),
    ("models", ("wmr_mujoco.models",)),
    ("sim", ("wmr_mujoco.sim",)),
    ("validation", ("wmr_mujoco.validation",)),
    ("loop", ("wmr_mujoco.loop",)),
    ("robots", ("wmr_mujoco.robots",)),
    ("application", ()),
)
RANK = {name: i for i, (name, _) in enumerate(LAYERS)}


def module_name(path: Path) -> str:
    parts = list(path.relative_to(SRC).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def modules() -> dict[str, Path]:
    return {module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def layer_of(module: str) -> str:
    best, best_len = "application", -1
    for name, prefixes in LAYERS:
        for prefix in prefixes:
            exact = prefix == "wmr_mujoco"
            hit = module == prefix if exact else (
                module == prefix or module.startswith(prefix + "."))
            if hit and len(prefix) > best_len:
                best, best_len = name, len(prefix)
    return best


def imports(module: str, path: Path) -> list[tuple[str, int]]:
    """``(imported module, line)`` for every import of the package in ``path``.

    ``from a.b import c`` counts as an import of ``a.b.c`` when ``a/b/c`` is a module,
    else of ``a.b``; relative imports are resolved against the module's package.
    """
    known = modules()
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(a.name, node.lineno) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            for alias in node.names:
                sub = f"{target}.{alias.name}"
                found.append((sub if sub in known else target, node.lineno))
    return [(t, line) for t, line in found if t == "wmr_mujoco" or t.startswith("wmr_mujoco.")]


def edges() -> list[tuple[str, str, int]]:
    return sorted({(m, t, line) for m, p in modules().items() for t, line in imports(m, p)})


def layer(unit_name: str) -> str:
    """The layer of a cycle-check node (:func:`unit`)."""
    return unit_name.rsplit("(", 1)[1].rstrip(")")


def unit(module: str) -> str:
    """The node of the cycle check: the subpackage, split where it spans layers."""
    return f"{'.'.join(module.split('.')[:2])} ({layer_of(module)})"


def test_layers_are_assigned_as_documented() -> None:
    # The classification itself, on modules whose place the docstring names.
    assert layer_of("wmr_mujoco") == "core"
    assert layer_of("wmr_mujoco.render.gl_backend") == "core"
    assert layer_of("wmr_mujoco.render.video") == "application"
    assert layer_of("wmr_mujoco.models.params") == "parameters"
    assert layer_of("wmr_mujoco.models.params.wheeled") == "parameters"
    assert layer_of("wmr_mujoco.models.builders.common") == "models"
    assert layer_of("wmr_mujoco.robots.steered.builder") == "robots"
    assert layer_of("wmr_mujoco.robots.whipple.params") == "robots"
    assert layer_of("wmr_mujoco.robots.roller_wheels.omni_kinematics") == "robots"
    assert layer_of("wmr_mujoco.robots.omni3.runs") == "robots"
    assert layer_of("wmr_mujoco.bench.omni_study") == "application"
    assert layer_of("wmr_mujoco.loop.control.paths") == "loop"
    assert layer_of("wmr_mujoco.drive.make") == "application"


def test_no_import_runs_up_the_layers() -> None:
    upward = [f"{m}:{line} imports {t} ({layer_of(m)} -> {layer_of(t)})"
              for m, t, line in edges() if RANK[layer_of(t)] > RANK[layer_of(m)]]
    assert not upward, "imports that run back up the layers:\n" + "\n".join(upward)


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one node (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    out: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_cycle_finder_finds_a_planted_cycle() -> None:
    # The finder itself: a -> b -> c -> a is one cycle, d hangs off it.
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a", "d"}, "d": set()}
    assert _cycles(graph) == [["a", "b", "c"]]


def test_no_cycle_between_subpackages() -> None:
    graph: dict[str, set[str]] = {}
    lines: dict[tuple[str, str], list[str]] = {}
    for m, t, line in edges():
        a, b = unit(m), unit(t)
        if a != b and "wmr_mujoco" not in (m, t):
            graph.setdefault(a, set()).add(b)
            lines.setdefault((a, b), []).append(f"{m}:{line} imports {t}")
    cycles = _cycles(graph)
    # The imports that close each cycle: those that do not run down the layers.
    detail = [f"cycle {c}:\n  " + "\n  ".join(
        s for a in c for b in c if RANK[layer(b)] >= RANK[layer(a)]
        for s in lines.get((a, b), [])) for c in cycles]
    assert not cycles, "subpackages that import each other:\n" + "\n".join(detail)


@pytest.mark.parametrize("path", sorted(PACKAGE.rglob("*.py")), ids=lambda p: module_name(p))
def test_module_is_short(path: Path) -> None:
    n = len(path.read_text(encoding="utf-8").splitlines())
    assert n <= MAX_LINES, f"{path.relative_to(SRC)} has {n} lines (at most {MAX_LINES})"
