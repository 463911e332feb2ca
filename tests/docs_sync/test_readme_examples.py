"""Every Python example in the README runs as written.

Each fenced ``python`` block of README.md is executed top to bottom in a fresh namespace,
in a temporary working folder, with matplotlib's non-interactive backend: a user who
copies an example gets what the README says, or this test fails.
"""

import math
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BLOCK = re.compile(r"```python\n(.*?)```", re.S)
EXAMPLES = BLOCK.findall((ROOT / "README.md").read_text())


def test_the_readme_has_examples():
    assert EXAMPLES, "README.md has no ```python example"


@pytest.mark.parametrize("code", EXAMPLES, ids=lambda c: c.strip().splitlines()[0][:60])
def test_example_runs(code, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    exec(compile(code, "README.md example", "exec"), {"__name__": "__readme__"})


def test_the_go_to_goal_example_arrives_as_the_readme_says(tmp_path, monkeypatch):
    """'close to the goal': within the law's arrival distance (GoToPose.tolerance, 1 mm)
    plus the physics' coasting after the last command (bounded at 1 mm more), and the
    heading within 0.01 rad (Astolfi's law drives β and α to zero together)."""
    code = next(c for c in EXAMPLES if "GoToPose" in c)
    monkeypatch.chdir(tmp_path)
    scope: dict[str, object] = {"__name__": "__readme__"}
    exec(compile(code, "README.md example", "exec"), scope)
    x, y, heading = scope["state"].pose
    assert math.hypot(x - 1.0, y - 0.5) <= 2e-3
    assert abs(heading - 1.57) <= 0.01
