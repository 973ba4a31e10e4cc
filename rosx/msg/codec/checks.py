"""Find the field that made serialisation fail, and say what is wrong with it.

The generated serialisers do not check values up front (genpy does not either); they pack, and
when packing fails this module walks the message and names the first field whose value cannot
be written in its wire type, with genpy's wording where genpy has one
(``field linear.x must be float type``, ``field data exceeds specified width [uint8]``).
"""

from __future__ import annotations

import struct
from typing import Any

from rosx.msg.codec.message import Message, SerializationError
from rosx.msg.codec.rostime import Duration, Time
from rosx.msg.codec.source import python_names
from rosx.msg.codec.wiretypes import BYTE_ARRAY_TYPES, INTEGER_RANGES, PACK_CHARS, TIME_CHARS
from rosx.msg.spec import HEADER_TYPE, Field

_UNSIGNED = frozenset({"uint8", "char", "uint16", "uint32", "uint64"})


def serialization_error(msg: Message, exc: BaseException) -> SerializationError:
    """The error to raise for ``exc`` from serialising ``msg``."""
    problem = find_problem(msg)
    if problem is None:
        problem = f"cannot serialize {msg._type}: {exc}"
    return SerializationError(problem)


def find_problem(msg: Message) -> str | None:
    """The first problem with ``msg``'s field values, or None if every one can be written."""
    spec = type(msg)._spec
    if spec is None:
        return None
    for field, attr in zip(spec.fields, python_names(spec), strict=True):
        try:
            value = getattr(msg, attr)
        except AttributeError:
            return f"field {field.name} is not set"
        problem = _field_problem(field, value, field.name)
        if problem is not None:
            return problem
    return None


def _field_problem(field: Field, value: Any, path: str) -> str | None:
    if not field.is_array:
        return _scalar_problem(field.base_type, value, path)
    base, size = field.base_type, field.array_len
    if base in BYTE_ARRAY_TYPES and isinstance(value, bytes | bytearray):
        return None  # bytes of another length than N are padded or cut, as by genpy
    if base in BYTE_ARRAY_TYPES and not isinstance(value, list | tuple):
        return f"field {path} must be bytes or a list of ints, not {type(value).__name__}"
    if isinstance(value, str | bytes | bytearray):
        return f"field {path} must be a list or tuple type. Only uint8[] can be a string"
    try:
        count = len(value)
    except TypeError:
        return f"field {path} must be a list or tuple type"
    if size is not None and count != size:
        return f"field {path} must have {size} elements, not {count}"
    for index, element in enumerate(value):
        problem = _scalar_problem(base, element, f"{path}[{index}]")
        if problem is not None:
            return problem
    return None


def _scalar_problem(base: str, value: Any, path: str) -> str | None:
    if base in PACK_CHARS:
        return _number_problem(base, value, path)
    if base in TIME_CHARS:
        return _time_problem(base, value, path)
    if base == "string":
        if isinstance(value, bytes):
            return f"field {path} must be a str, not bytes (strings are sent as UTF-8)"
        if not isinstance(value, str):
            return f"field {path} must be of type str"
        try:
            value.encode()
        except UnicodeEncodeError as exc:
            return f"field {path} cannot be encoded as UTF-8: {exc}"
        return None
    if not isinstance(value, Message):
        return f"field {path} must be of type [{base}]"
    if value._type != base and not (base == HEADER_TYPE and value._type == "roslib/Header"):
        return f"field {path} must be of type {base} instead of {value._type}"
    spec = type(value)._spec
    if spec is None:
        return None
    for field, attr in zip(spec.fields, python_names(spec), strict=True):
        try:
            inner = getattr(value, attr)
        except AttributeError:
            return f"field {path}.{field.name} is not set"
        problem = _field_problem(field, inner, f"{path}.{field.name}")
        if problem is not None:
            return problem
    return None


def _number_problem(base: str, value: Any, path: str) -> str | None:
    try:
        struct.pack("<" + PACK_CHARS[base], value)
    except (struct.error, TypeError, OverflowError, ValueError) as exc:
        if base == "bool":
            return f"field {path} is not a bool"
        if base in ("float32", "float64"):
            if isinstance(value, float | int):
                return f"field {path} does not fit in {base}: {exc}"
            return f"field {path} must be float type"
        if not hasattr(value, "__index__"):
            kind = "unsigned integer" if base in _UNSIGNED else "an integer"
            return f"field {path} must be {kind} type"
        low, _ = INTEGER_RANGES[base]
        if base in _UNSIGNED and value < low:
            return f"field {path} must be unsigned integer type"
        return f"field {path} exceeds specified width [{base}]"
    return None


def _time_problem(base: str, value: Any, path: str) -> str | None:
    kind, name = (Time, "Time") if base == "time" else (Duration, "Duration")
    if not isinstance(value, kind):
        try:
            struct.pack("<2" + TIME_CHARS[base], value.secs, value.nsecs)
        except (AttributeError, struct.error, TypeError):
            return f"field {path} must be of type {name}"
        return None
    width = "uint32" if base == "time" else "int32"
    for part in ("secs", "nsecs"):
        problem = _number_problem(width, getattr(value, part), f"{path}.{part}")
        if problem is not None:
            return problem
    return None
