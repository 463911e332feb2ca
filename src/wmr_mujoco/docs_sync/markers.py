"""Generated text in Markdown files, between ``<!-- key: begin -->`` and ``<!-- key: end -->``.

READMEs keep their prose by hand and their figures from code: the text between a pair of
markers is replaced wholesale by what a generator produced.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Mapping
from pathlib import Path

from wmr_mujoco.atomic import write_text_atomic


def markers(key: str) -> tuple[str, str]:
    """The begin and end marker lines for ``key``."""
    return f"<!-- {key}: begin -->", f"<!-- {key}: end -->"


def has_markers(path: Path, key: str) -> bool:
    """Whether ``path`` exists and holds both markers of ``key``."""
    if not path.is_file():
        return False
    text = path.read_text()
    return all(m in text for m in markers(key))


def _split(path: Path, key: str) -> tuple[str, str, str]:
    """``(head, body, tail)`` of ``path`` around the markers of ``key`` (markers left out).

    Raises:
        FileNotFoundError: ``path`` does not exist.
        ValueError: the markers are missing, repeated or out of order; the message names
            them and the file.
    """
    begin, end = markers(key)
    text = Path(path).read_text()
    if text.count(begin) != 1 or text.count(end) != 1 or text.index(begin) > text.index(end):
        raise ValueError(f"{path} must hold {begin!r} once, then {end!r} once")
    head, rest = text.split(begin, 1)
    body, tail = rest.split(end, 1)
    return head, body, tail


def replace_between(path: Path, key: str, body: str) -> None:
    """Replace the text between the markers of ``key`` in ``path`` with ``body`` (atomic).

    Raises:
        FileNotFoundError: ``path`` does not exist.
        ValueError: the markers are missing, repeated or out of order; the message names
            them and the file.
    """
    begin, end = markers(key)
    head, _, tail = _split(path, key)
    write_text_atomic(Path(path), f"{head}{begin}\n{body.strip()}\n{end}{tail}")


def between(path: Path, key: str) -> str:
    """The text between the markers of ``key`` in ``path``, stripped (as pasted).

    Raises:
        FileNotFoundError: ``path`` does not exist.
        ValueError: the markers are missing, repeated or out of order.
    """
    return _split(path, key)[1].strip()


def study_parser(description: str | None) -> argparse.ArgumentParser:
    """The command line of a study that pastes its tables: ``--no-write`` prints only."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--no-write", action="store_true", help="print only")
    return parser


def publish(path: Path, tables: Mapping[str, str], write: bool) -> None:
    """Print each generated table (by marker key) and, if ``write``, paste it into ``path``.

    Raises:
        ValueError: a key's markers are missing from ``path`` (:func:`replace_between`).
    """
    print("\n\n".join(tables.values()))
    if write:
        for key, text in tables.items():
            replace_between(path, key, text)
        print(f"wrote {path}")


def fixed(x: float, digits: int = 2) -> str:
    """A generated table's cell: ``x`` to ``digits`` decimals, ``n/a`` when not finite."""
    return "n/a" if not math.isfinite(x) else f"{x:.{digits}f}"
