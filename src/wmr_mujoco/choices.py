"""Enumerated choices taken at the public edge as members or as their string values."""

from __future__ import annotations

import enum
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
