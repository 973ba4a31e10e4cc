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

from rosx.msg.codec.rostime import Duration, Time, TVal
from rosx.msg.spec import PRIMITIVE_TYPES

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
    namespace: dict[str, Any] = {
        "new": object.__new__,
        "shared": frozenset(_SHARED),
        "value": _value,
    }
    lines = ["def clone(m):"]
    _write(lines, namespace, cls, "m", "n", 1)
    lines.append("    return n")
    exec("\n".join(lines), namespace)  # source built from the class's field names only
    function: Callable[[Any], Any] = namespace["clone"]
    _FUNCTIONS[cls] = function
    return function


def _write(
    lines: list[str], namespace: dict[str, Any], cls: type, src: str, dst: str, depth: int
) -> None:
    """Lines copying ``src`` (an instance of ``cls``) into a new ``dst``; nested messages of the
    declared class are copied inline, anything else through `_value`."""
    pad = "    " * depth
    name = f"C{len(namespace)}"
    namespace[name] = cls
    lines.append(f"{pad}{dst} = new({name})")
    slots = [slot for slot in _all_slots(cls) if slot != "_connection_header"]
    types: list[str] = list(getattr(cls, "_slot_types", []))
    resolver = getattr(cls, "_resolver", None)
    if (isinstance(cls, type) and issubclass(cls, TVal)) or len(types) != len(slots):
        types = ["int32"] * len(slots) if issubclass(cls, TVal) else ["?"] * len(slots)
    for index, (slot, kind) in enumerate(zip(slots, types, strict=True)):
        value = f"v{depth}_{index}"
        lines.append(f"{pad}{value} = {src}.{slot}")
        nested = _nested_class(kind, resolver)
        if kind in _SCALARS:
            lines.append(f"{pad}{dst}.{slot} = {value}")  # numbers and text: immutable
        elif nested is not None and depth < _INLINE_DEPTH:
            inner = f"w{depth}_{index}"
            klass = f"C{len(namespace)}"
            namespace[klass] = nested
            lines.append(f"{pad}if {value}.__class__ is {klass}:")
            _write(lines, namespace, nested, value, inner, depth + 1)
            lines.append(f"{pad}    {dst}.{slot} = {inner}")
            lines.append(f"{pad}else:")
            lines.append(f"{pad}    {dst}.{slot} = value({value})")
        else:
            lines.append(
                f"{pad}{dst}.{slot} = {value} if {value}.__class__ in shared else value({value})"
            )


#: The field types whose values are immutable Python objects: shared, never copied.
_SCALARS = PRIMITIVE_TYPES - {"time", "duration"}
_INLINE_DEPTH = 4


def _nested_class(kind: str, resolver: Any) -> type | None:
    if kind in ("time", "duration"):
        return Time if kind == "time" else Duration
    if "[" in kind or "/" not in kind or resolver is None:
        return None
    try:
        nested: type = resolver.class_of(kind)
    except Exception:  # an unknown type: copied generically
        return None
    return nested


def _all_slots(cls: type) -> list[str]:
    slots: list[str] = []
    for klass in reversed(cls.__mro__):
        names = klass.__dict__.get("__slots__", ())
        slots += [names] if isinstance(names, str) else list(names)
    return slots
