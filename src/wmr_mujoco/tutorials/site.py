"""MkDocs hooks of the documentation site (``mkdocs.yml``: ``hooks:``; ``make docs``).

* :func:`on_config`: drops ``nav`` entries whose page does not exist yet (the generated
  result and benchmark pages appear when their generator has run), so that a strict
  build passes with or without them;
* :func:`on_files`: adds every robot's clips from ``renders/``, and any picture or clip a
  page links outside ``docs/`` (the reports' plots), to the site under the same path
  (copied at build time, never into ``docs/``);
* :func:`on_page_markdown`: fills the gallery from the robots' registry, expands
  ``<!-- api: PACKAGE -->`` into one mkdocstrings block per module of ``PACKAGE``, and
  turns links that leave ``docs/`` for the repository (``../models/...``) into repository
  paths in code, since the site holds only ``docs/``;
* MathJax (for the tutorials' equations) is served from the site itself: the copy that
  the ``django-static-mathjax`` wheel ships (``docs`` extra), nothing from a CDN.

The pure functions below do the work and are tested without MkDocs
(``tests/tutorials/test_site.py``); the ``on_*`` names are MkDocs' event hooks.
"""

from __future__ import annotations

import json
import logging
import os
import posixpath
import re
import shutil
import tempfile
from collections.abc import Container, Iterable, Iterator
from pathlib import Path
from typing import Any

LOG = logging.getLogger("mkdocs.hooks.wmr")
#: Marker in ``docs/gallery.md`` that the generated gallery replaces.
GALLERY_MARKER = "<!-- gallery: generated -->"
#: Folder of the clips, relative to the repository root, and in the site.
RENDERS = "renders"
#: ``<!-- api: wmr_mujoco.analytic -->``: every public module of that package.
_API = re.compile(r"<!-- api: ([\w.]+) -->")
#: The MathJax bundle the site serves, its configuration (inline ``$…$`` as in Jupyter).
MATHJAX = "javascripts/tex-svg.js"
MATHJAX_CONFIG = "javascripts/mathjax-config.js"
_MATHJAX_SETTINGS = """window.MathJax = {
  tex: {inlineMath: [["$", "$"], ["\\\\(", "\\\\)"]],
        displayMath: [["$$", "$$"], ["\\\\[", "\\\\]"]],
        processEscapes: true, processEnvironments: true},
  svg: {fontCache: "global"}
};
"""
#: Wider pages: the tutorials' code and printed output fit without scrolling.
STYLE = "stylesheets/wide.css"
_STYLE = ".md-grid { max-width: 1500px; }\n"
_LINK = re.compile(r"(!?)\[([^\]]*)\]\(([^)\s]+)\)")
_SHOWN = (".gif", ".png")


def prune_nav(nav: list[Any], exists: Any) -> list[Any]:
    """``nav`` without the pages for which ``exists(path)`` is false (empty sections too).

    Entries are MkDocs' nav items: a path, ``{title: path}`` or ``{title: [items]}``;
    external links (``scheme://``) are kept.
    """
    out: list[Any] = []
    for item in nav:
        if isinstance(item, dict):
            (title, value), = item.items()
            if isinstance(value, list):
                inner = prune_nav(value, exists)
                if inner:
                    out.append({title: inner})
            elif "://" in str(value) or exists(value):
                out.append(item)
        elif "://" in str(item) or exists(item):
            out.append(item)
    return out


def clip_files(robots: Iterable[Any]) -> Iterator[tuple[str, str, str]]:
    """``(robot, description, file name)`` of every clip of every registered robot."""
    for spec in robots:
        for clip in spec.clips:
            yield spec.name, spec.description, spec.clip_file(clip)


def gallery_markdown(robots: Iterable[Any], renders: Path) -> str:
    """A Markdown table: each robot, its one-line description and its clips.

    A clip that ``make renders`` has not written yet is named, not shown.
    """
    rows: dict[str, tuple[str, list[str]]] = {}
    for name, description, file in clip_files(robots):
        shown = rows.setdefault(name, (description, []))[1]
        if not (renders / file).is_file():
            shown.append(f"`{RENDERS}/{file}` (not rendered yet: `make renders`)")
        elif file.endswith(_SHOWN):
            shown.append(f"![{name}: {file}]({RENDERS}/{file})")
        else:
            shown.append(f"[{file}]({RENDERS}/{file})")
    lines = ["| robot | clip | what |", "|---|---|---|"]
    for name, (description, shown) in rows.items():
        lines.append(f"| `{name}` | {' '.join(shown)} | {description} |")
    return "\n".join(lines)


#: Files a page may show from outside ``docs/`` (clips, plots): carried into the site.
CARRIED = (".gif", ".png", ".svg", ".jpg", ".jpeg", ".mp4", ".webm")


def _outside(page_dir: str, target: str) -> str | None:
    """The repository path a relative link leaves ``docs/`` for.

    None if it stays inside ``docs/``, or leaves the repository too (MkDocs then reports
    it as a broken link).
    """
    if "://" in target or target.startswith(("#", "mailto:", "/")):
        return None
    path = posixpath.normpath(posixpath.join(page_dir, target.split("#")[0]))
    if not path.startswith("../") or path.startswith("../../"):
        return None
    return path[len("../"):]


def carried_files(markdown: str, page_dir: str) -> set[str]:
    """Repository paths of the pictures and clips outside ``docs/`` that a page links to."""
    found = (_outside(page_dir, m.group(3)) for m in _LINK.finditer(markdown))
    return {p for p in found if p and p.lower().endswith(CARRIED)}


def outside_links(markdown: str, page_dir: str, carried: Container[str] = ()) -> str:
    """Links and images whose target leaves ``docs/`` become the repository path in code.

    ``page_dir`` is the page's folder relative to ``docs/`` ('' at the top). A link
    ``[models/omni3/README.md](../models/omni3/README.md)`` from a top-level page becomes
    ``models/omni3/README.md (`models/omni3/README.md` in the repository)``; links inside
    ``docs/``, absolute URLs and anchors are left alone. Files in ``carried`` (repository
    paths the site holds under the same path, :func:`on_files`) keep their link, relative
    to the site's copy: ``../renders/x.gif`` from a top-level page becomes
    ``renders/x.gif``.
    """
    def repl(match: re.Match[str]) -> str:
        bang, text, target = match.groups()
        repo_path = _outside(page_dir, target)
        if repo_path is None:
            return match.group(0)
        if repo_path in carried:
            site_path = posixpath.relpath(repo_path, page_dir or ".")
            return f"{bang}[{text}]({site_path}{target[len(target.split('#')[0]):]})"
        shown = text.strip("`") or repo_path
        if shown == repo_path:
            return f"`{repo_path}` (in the repository)"
        return f"{text} (`{repo_path}` in the repository)"
    return _LINK.sub(repl, markdown)


def api_markdown(package: str) -> str:
    """One ``::: module`` block per public module of ``package`` (its ``MODULES``)."""
    import importlib

    mod = importlib.import_module(package)
    names = getattr(mod, "MODULES", None)
    if names is None:
        import pkgutil

        names = [m.name for m in pkgutil.iter_modules(mod.__path__)
                 if not m.name.startswith("_")]
    return "\n\n".join(f"::: {package}.{name}" for name in sorted(names))


def mathjax_bundle() -> Path | None:
    """The MathJax 3 SVG bundle shipped by ``django-static-mathjax`` (None: not installed)."""
    import importlib.util

    spec = importlib.util.find_spec("mathjax")
    if spec is None or not spec.submodule_search_locations:
        return None
    for root in spec.submodule_search_locations:
        path = Path(root) / "static" / "mathjax" / "es5" / "tex-svg.js"
        if path.is_file():
            return path
    return None


def _repo_root(config: Any) -> Path:
    return Path(config["docs_dir"]).resolve().parent


# -- MkDocs event hooks ----------------------------------------------------------------

_JUPYTER_DIR: list[Path] = []
#: Repository paths carried into the site by :func:`on_files`.
_CARRIED: set[str] = set()


def quiet_kernels() -> Path:
    """Point Jupyter at a private configuration: kernels over IPC sockets in a temp folder.

    The tutorials' kernels otherwise listen on local TCP without encryption, which
    ipykernel warns about on every page; the sockets' files go in the same folder,
    removed after the build (:func:`on_post_build`). The HTML exporter's note that plot
    images carry no alternative text is silenced too: the lab template it uses has no
    place for one, and it inserts a placeholder itself.
    """
    folder = Path(tempfile.mkdtemp(prefix="wmr-docs-jupyter-"))
    settings = {"KernelManager": {"transport": "ipc", "ip": str(folder / "kernel")}}
    (folder / "jupyter_nbconvert_config.json").write_text(json.dumps(settings))
    os.environ["JUPYTER_CONFIG_DIR"] = str(folder)
    logging.getLogger("traitlets").setLevel(logging.ERROR)
    _JUPYTER_DIR.append(folder)
    return folder


def on_config(config: Any) -> Any:
    """Drop nav entries whose page is missing (generated pages not generated yet)."""
    quiet_kernels()
    docs = Path(config["docs_dir"])
    if config.get("nav"):
        kept = prune_nav(config["nav"], lambda p: (docs / p).is_file())
        if kept != config["nav"]:
            LOG.info("nav: pages not present are left out of the site's navigation")
        config["nav"] = kept
    return config


def on_files(files: Any, config: Any) -> Any:
    """Add MathJax, the robots' clips and the pictures pages link outside ``docs/``.

    Each carried file keeps its repository path in the site (``renders/x.gif``,
    ``reports/plots/y.png``): the generated result pages may show the reports' plots.
    """
    from mkdocs.structure.files import File

    from wmr_mujoco.robots import ROBOTS

    bundle = mathjax_bundle()
    if bundle is None:
        LOG.warning("MathJax is missing: install the docs extra (pip install -e '.[docs]')")
    else:
        files.append(File.generated(config, MATHJAX, abs_src_path=str(bundle)))
    files.append(File.generated(config, MATHJAX_CONFIG, content=_MATHJAX_SETTINGS))
    files.append(File.generated(config, STYLE, content=_STYLE))
    root = _repo_root(config)
    wanted = {f"{RENDERS}/{name}" for _, _, name in clip_files(ROBOTS.values())}
    for page in files.documentation_pages():
        if page.src_uri.endswith(".md"):
            wanted |= carried_files(Path(page.abs_src_path).read_text(encoding="utf-8"),
                                    posixpath.dirname(page.src_uri))
    for path in sorted(wanted):
        if (root / path).is_file() and files.get_file_from_path(path) is None:
            files.append(File(path, str(root), config["site_dir"], config["use_directory_urls"]))
            _CARRIED.add(path)
    return files


def on_post_build(config: Any) -> None:
    """Remove the private Jupyter folder of :func:`quiet_kernels`."""
    while _JUPYTER_DIR:
        shutil.rmtree(_JUPYTER_DIR.pop(), ignore_errors=True)


def on_page_markdown(markdown: str, page: Any, config: Any, files: Any) -> str:
    """Fill the gallery; rewrite links that leave ``docs/``."""
    if GALLERY_MARKER in markdown:
        from wmr_mujoco.robots import ROBOTS

        table = gallery_markdown(ROBOTS.values(), _repo_root(config) / RENDERS)
        markdown = markdown.replace(GALLERY_MARKER, table)
    markdown = _API.sub(lambda m: api_markdown(m.group(1)), markdown)
    return outside_links(markdown, posixpath.dirname(page.file.src_uri), _CARRIED)
