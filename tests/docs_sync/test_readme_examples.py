"""Every Python example in the README runs as written.

Each fenced ``python`` block of README.md is executed top to bottom in a fresh namespace,
in a temporary working folder, with matplotlib's non-interactive backend: a user who
copies an example gets what the README says, or this test fails.
"""

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
