"""Paste the latest reports into the README: ``python -m wmr_mujoco.docs_sync.readme_sync``.

``make demo`` writes ``reports/summary.md`` and ``reports/open.md`` (the open targets) and
``make bench`` writes ``reports/bench.md``; this copies them between the README's
``validation results``, ``open targets`` and ``benchmarks`` markers
(:mod:`wmr_mujoco.docs_sync.markers`), so that every figure in the README comes from a run of the
code, never from typing. ``make readme`` runs it.
"""

from __future__ import annotations

import argparse
import re
import sys
from collections.abc import Sequence
from pathlib import Path

from wmr_mujoco.docs_sync.markers import replace_between
from wmr_mujoco.models.paths import README_PATH
from wmr_mujoco.validation.report import REPORTS_DIR

#: README marker key -> (report file, command that writes it).
SECTIONS = {"validation results": ("summary.md", "make demo"),
            "open targets": ("open.md", "make demo"),
            "benchmarks": ("bench.md", "make bench")}


def section_text(report: str) -> str:
    """A report as a README section: its ``#`` title dropped, its ``##`` headings as ``####``."""
    lines = report.strip().splitlines()
    if lines and lines[0].startswith("# "):
        lines = lines[1:]
    return re.sub(r"^## ", "#### ", "\n".join(lines).strip(), flags=re.MULTILINE)


def sync(readme: Path = README_PATH, reports: Path = REPORTS_DIR,
         keys: Sequence[str] | None = None) -> list[str]:
    """Replace each README section (all, or those in ``keys``) with its report.

    Every requested report is checked before anything is written, so a missing one
    leaves the README as it was.

    Returns:
        The keys updated.

    Raises:
        FileNotFoundError: a report is missing; the message says which command writes it.
        ValueError: an unknown key, or the README lacks a section's markers.
    """
    keys = list(SECTIONS) if keys is None else list(keys)
    unknown = [k for k in keys if k not in SECTIONS]
    if unknown:
        raise ValueError(f"unknown README sections {unknown}; valid: {', '.join(SECTIONS)}")
    texts = {}
    for key in keys:
        name, command = SECTIONS[key]
        path = Path(reports) / name
        if not path.is_file():
            raise FileNotFoundError(f"{path} not found; `{command}` writes it")
        texts[key] = section_text(path.read_text())
    for key, text in texts.items():
        replace_between(readme, key, text)
    return keys


def main(argv: list[str] | None = None) -> int:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--readme", type=Path, default=README_PATH)
    parser.add_argument("--reports", type=Path, default=REPORTS_DIR)
    parser.add_argument("--only", action="append", choices=list(SECTIONS),
                        help="paste only this section (repeatable; default: all)")
    args = parser.parse_args(argv)
    try:
        keys = sync(args.readme, args.reports, args.only)
    except (FileNotFoundError, ValueError) as err:
        print(f"error: {err}", file=sys.stderr)
        return 2
    print(f"updated {args.readme}: {', '.join(keys)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
