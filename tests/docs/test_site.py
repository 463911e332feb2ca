"""The documentation site builds offline with warnings as errors (``mkdocs build --strict``).

Skipped, with the reason, where the ``docs`` extra is not installed. The tutorials are
rendered without executing them here (``WMR_DOCS_EXECUTE=false``): their execution is
tests/docs/test_tutorials.py's job, and ``make docs`` executes them.
"""

from __future__ import annotations

import importlib.util
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from wmr_mujoco.robots import ROBOTS
from wmr_mujoco.tutorials.site import clip_files

ROOT = Path(__file__).resolve().parents[2]
# The docs extra's check: `make test-extra` installs the extra and runs this (CI does),
# so a missing or broken docs install fails here rather than being skipped.
pytestmark = pytest.mark.extra


def test_the_docs_extra_is_installed():
    missing = [m for m in ("mkdocs", "material", "mkdocstrings_handlers", "mkdocs_jupyter",
                           "mathjax") if importlib.util.find_spec(m) is None]
    assert not missing, f"docs extra incomplete (pip install -e '.[docs]'): {missing}"


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("site")
    env = {**os.environ, "WMR_DOCS_EXECUTE": "false", "NO_MKDOCS_2_WARNING": "1"}
    proc = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "-d", str(out)],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-4000:]
    return out


def test_every_page_is_built(site: Path) -> None:
    assert (site / "index.html").is_file()
    for path in sorted((ROOT / "docs" / "tutorials").glob("[0-9][0-9]_*.py")):
        assert (site / "tutorials" / path.stem / "index.html").is_file(), path.name
    for page in ("analytical", "rolling-disc", "omni-dynamics", "mecanum", "gallery"):
        assert (site / page / "index.html").is_file(), page
    api = (site / "api" / "analytic" / "index.html").read_text()
    assert "wmr_mujoco.analytic.unicycle" in api
    assert "wmr_mujoco.robots.roller_wheels.omni_dynamics" in api


def test_the_gallery_shows_every_rendered_clip(site: Path) -> None:
    gallery = (site / "gallery" / "index.html").read_text()
    for robot, _, name in clip_files(ROBOTS.values()):
        assert f"<code>{robot}</code>" in gallery, robot
        if (ROOT / "renders" / name).is_file() and name.endswith(".gif"):
            assert f'src="../renders/{name}"' in gallery, name
            assert (site / "renders" / name).is_file(), name


def test_nothing_is_loaded_from_outside(site: Path) -> None:
    # Offline: no script, style sheet, font or image from another host; MathJax is local.
    remote = re.compile(r"""(?:src|href)=["']https?://|url\(["']?https?://|@import\s+["']?https?:""")
    for page in site.rglob("*.html"):
        text = page.read_text(errors="replace")
        for match in remote.finditer(text):
            context = text[match.start():match.start() + 120]
            # Hyperlinks (<a href>) to public sources are allowed; loaded resources are not.
            tag = text.rfind("<", 0, match.start())
            assert text[tag:tag + 2] == "<a", f"{page.relative_to(site)}: {context}"
    assert (site / "javascripts" / "tex-svg.js").stat().st_size > 100_000
