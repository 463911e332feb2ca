"""Field checks of the parameter dataclasses.

Each names the field, its value and the valid range (``ValueError``) or type
(``TypeError``).
"""

from __future__ import annotations

import math
from dataclasses import fields, is_dataclass
from typing import Any


def _is_number(value: object) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _check_range(obj: Any, name: str, low: float, high: float = math.inf,
                 low_inclusive: bool = False, high_inclusive: bool = True) -> None:
    """Raise ``ValueError`` unless ``low < obj.name <= high`` (bounds as the flags say).

    A value that is not a number (a string, None, a bool) is refused the same way.
    """
    value = getattr(obj, name)
    ok = _is_number(value) and math.isfinite(value)
    if ok:
        ok = ((value >= low if low_inclusive else value > low)
              and (value <= high if high_inclusive else value < high))
    if not ok:
        bracket = "[" if low_inclusive else "("
        close = "]" if high_inclusive and not math.isinf(high) else ")"
        high_txt = "inf" if math.isinf(high) else f"{high:g}"
        raise ValueError(
            f"{type(obj).__name__}.{name} = {value!r} is not physical; "
            f"valid range is {bracket}{low:g}, {high_txt}{close}"
        )


def _check_count(obj: Any, name: str, low: int, high: int) -> None:
    """Raise ``ValueError`` unless ``obj.name`` is an integer in ``[low, high]``."""
    value = getattr(obj, name)
    if not (isinstance(value, int) and not isinstance(value, bool) and low <= value <= high):
        raise ValueError(f"{type(obj).__name__}.{name} = {value!r}; valid range is "
                         f"integers [{low}, {high}]")


def _check_choice(obj: Any, name: str, choices: tuple[str, ...]) -> None:
    """Raise ``ValueError`` unless ``obj.name`` is one of ``choices``."""
    value = getattr(obj, name)
    if value not in choices:
        raise ValueError(f"{type(obj).__name__}.{name} = {value!r}; valid values are "
                         f"{', '.join(choices)}")


#: Field annotations (as strings: ``from __future__ import annotations``) of numbers.
_NUMBER_TYPES = ("float", "int")
#: Annotations of tuples of numbers, with their lengths.
_TUPLE_TYPES = {"tuple[float, float]": 2, "tuple[float, float, float]": 3,
                "tuple[float, float, float, float]": 4}


def _type_error(obj: Any, name: str, annotation: str, default: object) -> str | None:
    """Why ``obj.name`` does not fit its annotation, or None if it does."""
    value = getattr(obj, name)
    if annotation == "int" and not (isinstance(value, int) and not isinstance(value, bool)):
        return "is not an integer; give an integer"
    if annotation == "float" and not _is_number(value):
        return "is not a number; give a number (SI units)"
    if annotation in _TUPLE_TYPES:
        n = _TUPLE_TYPES[annotation]
        if not (isinstance(value, tuple) and len(value) == n
                and all(_is_number(v) and math.isfinite(v) for v in value)):
            return f"is not {n} finite numbers; give a tuple of {n} numbers (SI units)"
    if annotation == "str" and not isinstance(value, str):
        return "is not a string; give a string"
    if annotation == "bool" and not isinstance(value, bool):
        return "is not True or False; give a bool"
    if is_dataclass(default) and not isinstance(value, type(default)):
        return f"is not a {type(default).__name__}; give a {type(default).__name__}"
    return None


def _check_types(obj: Any) -> None:
    """Raise ``ValueError`` for a field of the wrong type, before any arithmetic on it.

    Number fields (annotated ``float``/``int``) must hold numbers (``int`` fields
    integers); tuple fields a tuple of that many finite numbers; a field whose default is
    a parameter dataclass an instance of that dataclass; ``str``/``bool`` fields a string
    or a bool. The message names the class, the field and the value.
    """
    for f in fields(obj):
        why = _type_error(obj, f.name, str(f.type), f.default)
        if why is not None:
            raise ValueError(f"{type(obj).__name__}.{f.name} = {getattr(obj, f.name)!r} {why}")


def _check_positive_fields(obj: Any, exclude: tuple[str, ...] = ()) -> None:
    """Check every field's type, then that each number field not in ``exclude`` is > 0."""
    _check_types(obj)
    for f in fields(obj):
        if f.name not in exclude and _is_number(getattr(obj, f.name)):
            _check_range(obj, f.name, 0.0)


def _check_floor_pair(obj: Any) -> None:
    """``floor_impedance`` 0 or in [1e-4, 0.01]."""
    if obj.floor_impedance != 0.0:
        _check_range(obj, "floor_impedance", 1e-4, 0.01, low_inclusive=True)


def _check_mesh_rollers(obj: Any, mesh: str) -> None:
    """A convex-mesh roller (``roller_shape == mesh``) only with ``floor_impedance`` 0.

    A mesh touches the floor at several points at once; against the floor pairs' soft
    contact (the remedy, ``floor_impedance`` > 0) those contacts throw the robot off the
    floor at the robots' steps (``tests/robots/mecanum4/test_params.py``), so the
    combination is refused rather than run.
    """
    if obj.roller_shape == mesh and obj.floor_impedance != 0.0:
        others = ", ".join(repr(s) for s in obj.ROLLER_SHAPES if s != mesh)
        raise ValueError(f"{type(obj).__name__}.roller_shape = {mesh!r} with floor_impedance "
                         f"= {obj.floor_impedance!r}: a mesh roller touches the floor at "
                         "several points, and against the floor pairs' soft contact they "
                         "throw the robot off the floor; valid: floor_impedance = 0 (contact "
                         f"bits) with {mesh!r}, or roller_shape {others} with the pairs")
