"""Deep copies of messages, generated per class: what an in-process subscriber receives.

`clone` copies a message so that neither side sees the other's later changes, as if the
message had been serialized and read back, at a fraction of the cost (a ``geometry_msgs/Twist``
in about 1 µs against 3 µs for serializing and decoding and 24 µs for ``copy.deepcopy``).
Immutable values (numbers, ``str``, ``bytes``, tuples) are shared; lists are copied; nested
messages, ``time`` and ``duration`` values are copied field by field; anything else (a numpy
array, a ``bytearray``) is copied with its own ``copy()``, or ``copy.deepcopy`` as a last
resort. The copying function of each class is generated on first use and kept on the class.
"""

from __future__ import annotations

import copy
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.rostime import TVal

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.codec.message import Message

_SHARED = (int, float, str, bytes, bool, tuple, type(None))
_FUNCTIONS: dict[type, Callable[[Any], Any]] = {}


def clone(msg: Message) -> Message:
    """A deep copy of ``msg`` (see the module's docstring)."""
    function = _FUNCTIONS.get(msg.__class__)
    if function is None:
        function = _compile(msg.__class__)
    result: Message = function(msg)
    return result


def _value(value: Any) -> Any:
    """A copy of one field's value whatever it holds (the generated code's fallback)."""
    if value.__class__ in _SHARED:
        return value
    if value.__class__ is list:
        return [v if v.__class__ in _SHARED else _value(v) for v in value]
    function = _FUNCTIONS.get(value.__class__)
    if function is not None:
        return function(value)
    if isinstance(value, TVal) or hasattr(value, "_slot_types"):
        return _compile(value.__class__)(value)
    copier = getattr(value, "copy", None)
    if callable(copier):
        return copier()
    return copy.deepcopy(value)


def _compile(cls: type) -> Callable[[Any], Any]:
    slots = [slot for slot in _all_slots(cls) if slot != "_connection_header"]
    lines = ["def clone(m):", "    n = new(cls)"]
    for slot in slots:
        lines.append(f"    v = m.{slot}")
        lines.append(f"    n.{slot} = v if v.__class__ in shared else value(v)")
    lines.append("    return n")
    namespace: dict[str, Any] = {
        "new": object.__new__,
        "cls": cls,
        "shared": frozenset(_SHARED),
        "value": _value,
    }
    exec("\n".join(lines), namespace)  # source built from the class's slot names only
    function: Callable[[Any], Any] = namespace["clone"]
    _FUNCTIONS[cls] = function
    return function


def _all_slots(cls: type) -> list[str]:
    slots: list[str] = []
    for klass in reversed(cls.__mro__):
        names = klass.__dict__.get("__slots__", ())
        slots += [names] if isinstance(names, str) else list(names)
    return slots
