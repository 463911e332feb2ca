"""Paste the latest reports into the docs: ``python -m wmr_mujoco.docs_sync.readme_sync``.

``make demo`` writes ``reports/summary.md``, ``reports/open.md`` (the open targets) and
``reports/families.md`` (each family's spread), and ``make bench`` writes
``reports/bench.md``; this copies them between the ``validation results``, ``open
targets`` and ``validation families`` markers of ``docs/results.md`` and the
``benchmarks`` markers of ``docs/benchmarks.md`` (:mod:`wmr_mujoco.docs_sync.markers`),
so that every figure in the docs comes from a run of the code, never from typing.
``make readme`` runs it.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections.abc import Sequence
from pathlib import Path

from wmr_mujoco.docs_sync.markers import replace_between
from wmr_mujoco.models.paths import REPO_ROOT, REPORTS_DIR

#: Marker key -> (report file, command that writes it).
SECTIONS = {"validation results": ("summary.md", "make demo"),
            "open targets": ("open.md", "make demo"),
            "validation families": ("families.md", "make demo"),
            "benchmarks": ("bench.md", "make bench")}
#: Marker key -> the page that holds the section, relative to the repository root.
PAGES = {"validation results": "docs/results.md", "open targets": "docs/results.md",
         "validation families": "docs/results.md",
         "benchmarks": "docs/benchmarks.md"}


#: An absolute path of this machine in a report (``/home/...``, ``C:\\...``): not for the docs.
LOCAL_PATH = re.compile(r"(?:^|[\s`'\"(=])(?:/[\w.-]+){2,}|[A-Za-z]:\\\\")


def _json(path: Path) -> dict:
    try:
        doc = json.loads(path.read_text())
    except (OSError, ValueError):
        return {}
    return doc if isinstance(doc, dict) else {}


def refusal(key: str, reports: Path, text: str) -> str | None:
    """Why a report must not go into the docs (one line), or None if it may.

    Refused: a partial validation report (not every registered scenario, see
    ``validation.json``'s ``complete``) or a quick one (fewer draws than the families
    declare, ``quick``), a ``--quick`` or partial bench (the peer model
    left out), and any report naming a path of this machine.
    """
    reports = Path(reports)
    if SECTIONS[key][1] == "make demo":  # the validation results and open targets
        doc = _json(reports / "validation.json")
        if doc.get("complete") is not True:
            missing = doc.get("missing") or ["(validation.json missing or from an old run)"]
            shown = ", ".join(missing[:3]) + (f" and {len(missing) - 3} more"
                                              if len(missing) > 3 else "")
            return (f"{reports / SECTIONS[key][0]} is partial (not run: {shown}); run "
                    "`make demo`")
        if doc.get("quick"):
            return (f"{reports / SECTIONS[key][0]} is from a quick run (fewer draws than "
                    "the families declare); run `make demo`")
    if key == "benchmarks":
        doc = _json(reports / "bench.json")
        if doc.get("quick", True):
            return (f"{reports / 'bench.md'} is from `wmr bench --quick` (or has no "
                    "bench.json); run `make bench`")
        if doc.get("peer") is None:
            return (f"{reports / 'bench.md'} is partial (the peer model was not found); "
                    "install mujoco-menagerie or set WMR_PEER_SCENE, then `make bench`")
    match = LOCAL_PATH.search(text)
    if match:
        return (f"{reports / SECTIONS[key][0]} names a path of this machine "
                f"({match.group().strip()!r}); it would not hold for a reader")
    return None


def section_text(report: str) -> str:
    """A report as a docs section: its ``#`` title dropped, its ``##`` headings as ``####``."""
    lines = report.strip().splitlines()
    if lines and lines[0].startswith("# "):
        lines = lines[1:]
    return re.sub(r"^## ", "#### ", "\n".join(lines).strip(), flags=re.MULTILINE)


def sync(root: Path = REPO_ROOT, reports: Path = REPORTS_DIR,
         keys: Sequence[str] | None = None) -> list[str]:
    """Replace each section (all, or those in ``keys``) of the pages under ``root``.

    Every requested report is checked before anything is written, so a missing one
    leaves the pages as they were.

    Returns:
        The keys updated.

    Raises:
        FileNotFoundError: a report is missing; the message says which command writes it.
        ValueError: an unknown key, a report :func:`refusal` refuses (one line saying
            why), or a page lacks a section's markers.
    """
    keys = list(SECTIONS) if keys is None else list(keys)
    unknown = [k for k in keys if k not in SECTIONS]
    if unknown:
        raise ValueError(f"unknown sections {unknown}; valid: {', '.join(SECTIONS)}")
    texts = {}
    for key in keys:
        name, command = SECTIONS[key]
        path = Path(reports) / name
        if not path.is_file():
            raise FileNotFoundError(f"{path} not found; `{command}` writes it")
        text = path.read_text()
        reason = refusal(key, reports, text)
        if reason is not None:
            raise ValueError(f"not pasted: {reason}")
        texts[key] = section_text(text)
    for key, text in texts.items():
        replace_between(Path(root) / PAGES[key], key, text)
    return keys


def main(argv: list[str] | None = None) -> int:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=Path, default=REPO_ROOT,
                        help="the repository whose docs/ pages are written")
    parser.add_argument("--reports", type=Path, default=REPORTS_DIR)
    parser.add_argument("--only", action="append", choices=list(SECTIONS),
                        help="paste only this section (repeatable; default: all)")
    args = parser.parse_args(argv)
    try:
        keys = sync(args.root, args.reports, args.only)
    except (FileNotFoundError, ValueError) as err:
        print(f"error: {err}", file=sys.stderr)
        return 2
    print(f"updated {', '.join(sorted({PAGES[k] for k in keys}))}: {', '.join(keys)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
