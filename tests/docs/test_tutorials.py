"""Every tutorial (docs/tutorials/NN_*.py) runs top to bottom, and its exercise checks out.

Each tutorial is run as a script (runpy) with matplotlib's non-interactive backend, as a
student would run it outside Jupyter. Its solution cell leaves ``result``, the
:class:`~wmr_mujoco.tutorials.checks.CheckResult` of the reference answer, which must
pass; its exercise cell, run with the placeholder answer, must print a hint (``NOT YET``)
and not raise. The wall time of each is printed (``make tutorials`` shows it; no timing
assert).
"""

from __future__ import annotations

import re
import runpy
import time
from pathlib import Path

import matplotlib
import pytest

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from wmr_mujoco.tutorials.checks import CheckResult

ROOT = Path(__file__).resolve().parents[2]
TUTORIALS = sorted((ROOT / "docs" / "tutorials").glob("[0-9][0-9]_*.py"))


def test_the_lecture_sequence_is_complete() -> None:
    # The lecture's seven steps, in order, each listed in the site's nav and on its home page.
    assert [p.name[:2] for p in TUTORIALS] == [f"{i:02d}" for i in range(1, 8)]
    nav = (ROOT / "mkdocs.yml").read_text()
    home = (ROOT / "docs" / "index.md").read_text()
    for path in TUTORIALS:
        assert f"tutorials/{path.name}" in nav, path.name
        assert f"tutorials/{path.name}" in home, path.name


@pytest.mark.parametrize("path", TUTORIALS, ids=[p.stem for p in TUTORIALS])
def test_tutorial_runs_and_its_exercise_checks_out(path: Path, capsys) -> None:
    start = time.perf_counter()
    try:
        namespace = runpy.run_path(str(path), run_name="__main__")
    finally:
        plt.close("all")
    seconds = time.perf_counter() - start
    out = capsys.readouterr().out
    result = namespace.get("result")
    assert isinstance(result, CheckResult), "the solution cell must leave `result`"
    assert result.passed, result.message
    # The placeholder answer gets a hint, printed, not an exception.
    assert re.search(r"^NOT YET \[", out, re.M), out[-2000:]
    assert re.search(r"^PASS \[", out, re.M)
    # The run time is printed, measured, never typed into the page by hand.
    assert not re.search(r"Run time: about", path.read_text())
    with capsys.disabled():
        print(f"\n{path.name}: {seconds:.1f} s")
