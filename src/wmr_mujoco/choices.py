"""Choices taken at the public edge: enum members or their values, names typed loosely."""

from __future__ import annotations

import difflib
import enum
from collections.abc import Sequence
from typing import TypeVar

E = TypeVar("E", bound=enum.Enum)


def parse_choice(choices: type[E], value: E | str, what: str) -> E:
    """The member of ``choices`` that is, or has the value, ``value``.

    Raises:
        ValueError: no such member; the message names ``what``, the value and the valid ones.
    """
    try:
        return choices(value)
    except ValueError:
        valid = ", ".join(str(c.value) for c in choices)
        raise ValueError(f"unknown {what} {value!r}; valid {what}s are: {valid}") from None


def _normal(name: str) -> str:
    """A name as typed loosely: case-folded, degree signs dropped, spaces collapsed."""
    return " ".join(name.replace("°", " ").casefold().split())


def match_name(value: object, names: Sequence[str], what: str, missing: str = "",
               valid: str = "") -> str:
    """The one of ``names`` that ``value`` means: exact, else loose, else a unique prefix.

    Loose: case does not matter, nor a degree sign (``"translate 45"`` is
    ``"translate 45°"``), nor repeated spaces. A prefix matches when it is one name's
    alone (``"mec"`` is ``"mecanum4"``; ``"di"`` is several).

    Args:
        value: the name as given.
        names: the valid names.
        what: what a name names, e.g. ``"robot"``.
        missing: the error's opening when nothing matches (default ``unknown WHAT 'v'``).
        valid: the error's list of valid names (default ``valid WHATs are: a, b``).

    Raises:
        ValueError: no name matches (the message suggests the nearest ones, then lists
            the valid ones), or a prefix matches several (the message lists them).
    """
    if isinstance(value, str) and value in names:
        return value
    missing = missing or f"unknown {what} {value!r}"
    valid = valid or f"valid {what}s are: {', '.join(names)}"
    if not isinstance(value, str):
        raise ValueError(f"{missing}; {valid}")
    typed = _normal(value)
    loose = {_normal(n): n for n in names}
    if typed in loose:
        return loose[typed]
    starts = [n for k, n in loose.items() if typed and k.startswith(typed)]
    if len(starts) == 1:
        return starts[0]
    if starts:
        raise ValueError(f"{what} {value!r} is ambiguous: it begins "
                         f"{', '.join(map(repr, starts))}; give more of the name")
    near = difflib.get_close_matches(typed, list(loose), n=3, cutoff=0.6)
    shown = [repr(loose[k]) for k in near]
    if len(shown) > 1:
        shown = [", ".join(shown[:-1]), shown[-1]]
    hint = f"did you mean {' or '.join(shown)}? " if shown else ""
    raise ValueError(f"{missing}; {hint}{valid}")
