"""The site hooks' pure parts: nav pruning, the gallery, outside links, API blocks."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from wmr_mujoco.robots.spec import Clip
from wmr_mujoco.tutorials import site


def test_prune_nav_drops_missing_pages_and_empty_sections() -> None:
    nav = [{"Home": "index.md"}, {"Results": [{"Validation": "results.md"},
                                              {"Benchmarks": "benchmarks.md"}]},
           {"Tutorials": ["tutorials/01.py", "tutorials/02.py"]}, "https://example.org/x"]
    present = {"index.md", "tutorials/01.py"}
    assert site.prune_nav(nav, present.__contains__) == [
        {"Home": "index.md"}, {"Tutorials": ["tutorials/01.py"]}, "https://example.org/x"]
    present |= {"results.md"}
    assert {"Results": [{"Validation": "results.md"}]} in site.prune_nav(nav, present.__contains__)


def test_outside_links_become_repository_paths() -> None:
    text = ("see [`models/mecanum4/README.md`](../models/mecanum4/README.md), "
            "[the disc](../models/disc/README.md#frames), [inside](analytical.md), "
            "[web](https://example.org/a.md) and ![pic](renders/disc.gif)")
    out = site.outside_links(text, "")
    assert "`models/mecanum4/README.md` (in the repository)" in out
    assert "the disc (`models/disc/README.md` in the repository)" in out
    assert "[inside](analytical.md)" in out and "[web](https://example.org/a.md)" in out
    assert "![pic](renders/disc.gif)" in out
    # The clips are carried by the site: the link is kept, relative to the site's copy.
    carried = {"renders/disc.gif", "renders/a.gif"}
    assert (site.outside_links("![c](../renders/disc.gif)", "", carried)
            == "![c](renders/disc.gif)")
    assert (site.outside_links("[c](../../renders/a.gif)", "tutorials", carried)
            == "[c](../renders/a.gif)")
    assert site.outside_links("![c](../renders/disc.gif)", "") == (
        "c (`renders/disc.gif` in the repository)")
    # A link out of the repository is left for MkDocs to report.
    assert site.outside_links("[x](../../secret.md)", "") == "[x](../../secret.md)"
    # From a sub-folder, one level up stays inside docs/.
    assert site.outside_links("[a](../index.md)", "tutorials") == "[a](../index.md)"


def test_carried_files_are_pictures_and_clips_outside_docs() -> None:
    text = ("![p](../reports/plots/a.png) [r](../reports/validation.md) ![i](img/x.png) "
            "![c](../../renders/b.gif#t) [w](https://example.org/c.png)")
    assert site.carried_files(text, "") == {"reports/plots/a.png"}
    assert site.carried_files(text, "sub") == {"renders/b.gif"}


@dataclass(frozen=True)
class FakeSpec:
    name: str
    description: str
    clips: tuple[Clip, ...] = field(default=(Clip(),))

    def clip_file(self, clip: Clip) -> str:
        return clip.file or f"{self.name}.gif"


def test_gallery_lists_each_robot_and_names_missing_clips(tmp_path: Path) -> None:
    (tmp_path / "a.gif").write_bytes(b"GIF89a")
    (tmp_path / "b_fall.mp4").write_bytes(b"")
    robots = [FakeSpec("a", "robot a"),
              FakeSpec("b", "robot b", (Clip(), Clip(file="b_fall.mp4")))]
    md = site.gallery_markdown(robots, tmp_path)
    assert "| `a` | ![a: a.gif](renders/a.gif) | robot a |" in md
    assert "`renders/b.gif` (not rendered yet: `make renders`)" in md
    assert "[b_fall.mp4](renders/b_fall.mp4)" in md


def test_api_markdown_lists_every_analytic_module() -> None:
    from wmr_mujoco import analytic

    md = site.api_markdown("wmr_mujoco.analytic")
    assert md.count(":::") == len(analytic.MODULES)
    assert "::: wmr_mujoco.analytic.unicycle" in md


def test_quiet_kernels_uses_a_private_ipc_config(monkeypatch) -> None:
    import json
    import logging

    monkeypatch.delenv("JUPYTER_CONFIG_DIR", raising=False)
    level = logging.getLogger("traitlets").level
    try:
        folder = site.quiet_kernels()
        import os

        assert os.environ["JUPYTER_CONFIG_DIR"] == str(folder)
        settings = json.loads((folder / "jupyter_nbconvert_config.json").read_text())
        assert settings["KernelManager"]["transport"] == "ipc"
        assert settings["KernelManager"]["ip"].startswith(str(folder))
        site.on_post_build({})
        assert not folder.exists()
    finally:
        logging.getLogger("traitlets").setLevel(level)
