"""Reading message values generically: what is a message, its fields, and plain Python values.

Messages are recognised as rospy's tools recognise them, by shape: a class with ``__slots__`` (the
field names) and ``_slot_types`` (their resolved types), which is what generated classes carry.
`Time` and `Duration` carry ``_slot_types`` too and are told apart first. Values coming from numpy
(scalars, arrays) are turned into the Python values rospy would hold (float, int, tuple).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from rosx.msg.codec.rostime import TVal


def is_message(value: object) -> bool:
    """Whether ``value`` is a message (a generated class's instance), not a time value."""
    return not isinstance(value, TVal) and hasattr(value, "_slot_types")


def field_types(msg: object) -> Iterator[tuple[str, str]]:
    """``(name, resolved type)`` of each field of message ``msg``, in declaration order."""
    names: list[str] = list(getattr(msg, "__slots__", ()))
    types: list[str] = list(getattr(msg, "_slot_types", ()))
    return zip(names, types, strict=False)


def plain(value: Any) -> Any:
    """``value`` with numpy scalars and arrays replaced by Python numbers and tuples."""
    if type(value).__module__ == "numpy":
        if getattr(value, "ndim", None):
            return tuple(value.tolist())
        if hasattr(value, "item"):
            return value.item()
    return value


def has_header(msg: object) -> bool:
    """Whether ``msg`` starts with ``Header header`` (rospy's ``_has_header``)."""
    flag = getattr(msg, "_has_header", None)
    if flag is None:
        spec = getattr(msg, "_spec", None)
        flag = bool(getattr(spec, "has_header", False))
    return bool(flag)


__all__ = ["field_types", "has_header", "is_message", "plain"]
