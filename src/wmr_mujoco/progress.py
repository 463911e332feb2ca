"""Progress bars (tqdm) for the long commands: ``render``, ``validate`` and ``bench``.

A bar is drawn on standard error only when it is a terminal and ``--quiet`` was not
given, so logs, pipes and tests get no control characters.
"""

from __future__ import annotations

import sys

from tqdm import tqdm

_quiet = False


def configure(quiet: bool) -> None:
    """Silence every bar (``--quiet``), or let them show on a terminal."""
    global _quiet
    _quiet = bool(quiet)


def shown() -> bool:
    """Whether bars are drawn: standard error is a terminal and not ``--quiet``."""
    return not _quiet and sys.stderr.isatty()


def bar(total: int, desc: str, unit: str = "it") -> tqdm:
    """A bar of ``total`` steps (a disabled one when :func:`shown` is False)."""
    return tqdm(total=total, desc=desc, unit=unit, disable=not shown(), leave=False,
                file=sys.stderr, dynamic_ncols=True)
