"""Messages as rosbridge's JSON and CBOR values, and JSON values back into messages.

rosbridge v2 (rosbridge_suite's ``message_conversion`` and ``cbor_conversion``) encodes a
message as an object of its fields, in declaration order, with these rules:

- ``time`` and ``duration``: ``{"secs": s, "nsecs": n}``; a ``time`` may be given as ``"now"``.
- ``uint8[]`` and ``char[]`` (any length): the bytes in base64 for JSON; raw bytes for CBOR.
- ``float32``/``float64``: NaN and ±inf become ``null`` in JSON (which has no such numbers);
  CBOR keeps them.
- CBOR packs numeric arrays as the typed-array tags of RFC 8746 (little-endian).

Going back, a JSON value must have the field's kind (an integer is a float, a float is not an
integer, a bool is neither), fields left out keep their defaults, a ``Header``'s stamp is
"now" unless given, and a name that is not a field is refused. Errors name the message type,
the field path and what came, in rosbridge's wording, in JSON's names for the kinds.

Encoders and decoders are built once per message class from its `MsgSpec` (the classes of
`rosx.msg.codec.classes`: one type system, one codec), so a subscription pays no reflection
per message.
"""

from __future__ import annotations

import base64
import binascii
import math
import struct
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.rostime import Duration, Time
from rosx.msg.codec.source import python_name
from rosx.msg.codec.wiretypes import BYTE_ARRAY_TYPES, INTEGER_RANGES
from rosx.msg.spec import HEADER_TYPE

if TYPE_CHECKING:
    from rosx.msg.codec.message import Message
    from rosx.msg.spec import Field

Encoder = Callable[[Any], Any]

_FLOATS = frozenset({"float32", "float64"})
_TIMES = {"time": Time, "duration": Duration}
#: RFC 8746 tags and struct characters of the numeric arrays rosbridge's CBOR packs.
_TYPED_ARRAYS: dict[str, tuple[int, str]] = {
    "int8": (72, "b"),
    "byte": (72, "b"),
    "uint16": (69, "H"),
    "uint32": (70, "I"),
    "uint64": (71, "Q"),
    "int16": (77, "h"),
    "int32": (78, "i"),
    "int64": (79, "q"),
    "float32": (85, "f"),
    "float64": (86, "d"),
}


class ConversionError(ValueError):
    """JSON values that do not make a message of the type; the text says which field and why."""


# -- messages → JSON values ------------------------------------------------------------------


def _finite(value: float) -> float | None:
    return value if math.isfinite(value) else None


def _time_value(value: Any) -> dict[str, int]:
    return {"secs": value.secs, "nsecs": value.nsecs}


def _b64(value: Any) -> str:
    return base64.b64encode(bytes(value)).decode("ascii")


_json_encoders: dict[type, Encoder] = {}
_cbor_encoders: dict[type, Encoder] = {}


def json_values(msg: Message) -> dict[str, Any]:
    """``msg`` as rosbridge's JSON values (a dict ready for ``json.dumps``)."""
    cls = type(msg)
    encode = _json_encoders.get(cls)
    if encode is None:
        encode = _json_encoders[cls] = _message_encoder(cls, _json_field)
    result: dict[str, Any] = encode(msg)
    return result


def cbor_values(msg: Message) -> dict[str, Any]:
    """``msg`` as rosbridge's CBOR values (bytes and typed-array tags for ``cbor2.dumps``)."""
    cls = type(msg)
    encode = _cbor_encoders.get(cls)
    if encode is None:
        encode = _cbor_encoders[cls] = _message_encoder(cls, _cbor_field)
    result: dict[str, Any] = encode(msg)
    return result


def _message_encoder(
    cls: type[Message], field_encoder: Callable[[Field], Encoder | None]
) -> Encoder:
    spec = cls._spec
    assert spec is not None, f"{cls._type} has no definition"
    plan = [(f.name, python_name(f.name), field_encoder(f)) for f in spec.fields]

    def encode(msg: Any) -> dict[str, Any]:
        out = {}
        for key, attr, conv in plan:
            value = getattr(msg, attr)
            out[key] = value if conv is None else conv(value)
        return out

    return encode


def _nested(field: Field, field_encoder: Callable[[Field], Encoder | None]) -> Encoder:
    """The encoder of one value of the message type ``field.base_type``, built on first use."""
    built: list[Encoder] = []

    def encode(value: Any) -> Any:
        if not built:
            built.append(_message_encoder(get_message_class(field.base_type), field_encoder))
        return built[0](value)

    return encode


def _json_field(field: Field) -> Encoder | None:
    base = field.base_type
    if field.is_array:
        if base in BYTE_ARRAY_TYPES:
            return _b64
        if base in _FLOATS:
            return lambda values: [v if math.isfinite(v) else None for v in values]
        if base in _TIMES:
            return lambda values: [_time_value(v) for v in values]
        if field.is_builtin:
            return list
        one = _nested(field, _json_field)
        return lambda values: [one(v) for v in values]
    if base in _FLOATS:
        return _finite
    if base in _TIMES:
        return _time_value
    if field.is_builtin:
        return None
    return _nested(field, _json_field)


def _cbor_field(field: Field) -> Encoder | None:
    base = field.base_type
    if field.is_array:
        if base in BYTE_ARRAY_TYPES:
            return bytes
        typed = _TYPED_ARRAYS.get(base)
        if typed is not None:
            return _typed_array(*typed)
        if base in _TIMES:
            return lambda values: [_time_value(v) for v in values]
        if field.is_builtin:
            return list
        one = _nested(field, _cbor_field)
        return lambda values: [one(v) for v in values]
    if base in _TIMES:
        return _time_value
    if field.is_builtin:
        return None
    return _nested(field, _cbor_field)


def _typed_array(tag: int, char: str) -> Encoder:
    import cbor2  # noqa: PLC0415 - only CBOR subscriptions pay for it

    def encode(values: Any) -> Any:
        if hasattr(values, "tobytes"):  # a numpy array: already packed
            return cbor2.CBORTag(tag, values.astype("<" + char, copy=False).tobytes())
        return cbor2.CBORTag(tag, struct.pack(f"<{len(values)}{char}", *values))

    return encode


# -- JSON values → messages ------------------------------------------------------------------


def _kind(value: object) -> str:
    """``value``'s kind as JSON names it."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "boolean"
    if isinstance(value, int | float):
        return "number"
    if isinstance(value, str):
        return "string"
    if isinstance(value, list):
        return "array"
    if isinstance(value, dict):
        return "object"
    return type(value).__name__


class _Filler:
    """Fills one message of ``root`` type from JSON values; ``stamp`` is "now"."""

    def __init__(self, root: str, stamp: Time) -> None:
        self.root = root
        self.stamp = stamp

    def mismatch(self, path: list[str], expected: str, value: object) -> ConversionError:
        if not path:
            return ConversionError(
                f"Expected a JSON object for type {self.root} but received a {_kind(value)}"
            )
        return ConversionError(
            f"{self.root} message requires a {expected} for field {'.'.join(path)}, "
            f"but got a {_kind(value)}"
        )

    def message(self, cls: type[Message], values: object, path: list[str]) -> Message:
        spec = cls._spec
        assert spec is not None, f"{cls._type} has no definition"
        if not isinstance(values, dict):
            raise self.mismatch(path, spec.full_name, values)
        msg = cls()
        fields = {f.name: f for f in spec.fields}
        if spec.full_name == HEADER_TYPE:
            msg.stamp = Time(self.stamp.secs, self.stamp.nsecs)
        elif spec.has_header and "header" not in values:  # the spec's promise: stamped now
            msg.header.stamp = Time(self.stamp.secs, self.stamp.nsecs)
        for key, value in values.items():
            field = fields.get(key)
            if field is None:
                where = ".".join([*path, str(key)])
                raise ConversionError(f"Message type {self.root} does not have a field {where}")
            setattr(msg, python_name(key), self.field(field, value, [*path, key]))
        return msg

    def field(self, field: Field, value: object, path: list[str]) -> Any:
        base = field.base_type
        if not field.is_array:
            return self.scalar(base, value, path)
        data: bytes | list[Any]
        if base in BYTE_ARRAY_TYPES:
            data = self.byte_array(field, value, path)
        else:
            if not isinstance(value, list):
                raise self.mismatch(path, field.type, value)
            data = [self.scalar(base, item, [*path, str(i)]) for i, item in enumerate(value)]
        if field.array_len is not None and len(data) != field.array_len:
            raise ConversionError(
                f"{self.root} message requires {field.array_len} values for field "
                f"{'.'.join(path)}, but got {len(data)}"
            )
        return data

    def byte_array(self, field: Field, value: object, path: list[str]) -> bytes:
        if isinstance(value, str):
            try:
                return base64.b64decode(value, validate=True)
            except (binascii.Error, ValueError):
                raise ConversionError(
                    f"{self.root} message requires base64 text or an array of numbers for "
                    f"field {'.'.join(path)}, but got text that is not base64"
                ) from None
        if isinstance(value, list) and all(type(v) is int and 0 <= v <= 255 for v in value):
            return bytes(value)
        raise self.mismatch(path, field.type, value)

    def scalar(self, base: str, value: object, path: list[str]) -> Any:
        kind = type(value)
        if base in _FLOATS:
            if kind is float or kind is int:
                return float(value)  # type: ignore[arg-type]
        elif base in INTEGER_RANGES:
            if kind is int:
                low, high = INTEGER_RANGES[base]
                if not low <= value <= high:  # type: ignore[operator]
                    raise ConversionError(
                        f"{self.root} message requires a {base} for field {'.'.join(path)}, "
                        f"but {value} is out of its range [{low}, {high}]"
                    )
                return value
        elif base == "bool":
            if kind is bool:
                return value
        elif base == "string":
            if kind is str:
                return value
        elif base in _TIMES:
            return self.time(base, value, path)
        else:
            return self.message(get_message_class(base), value, path)
        raise self.mismatch(path, base, value)

    def time(self, base: str, value: object, path: list[str]) -> Time | Duration:
        if base == "time" and value == "now":
            return Time(self.stamp.secs, self.stamp.nsecs)
        if not isinstance(value, dict):
            raise self.mismatch(path, base, value)
        parts = []
        for key in ("secs", "nsecs"):
            part = value.get(key, 0)
            if type(part) is not int:
                raise self.mismatch([*path, key], "int32", part)
            parts.append(part)
        return Time(parts[0], parts[1]) if base == "time" else Duration(parts[0], parts[1])


def from_json(cls: type[Message], values: object, *, stamp: Time) -> Message:
    """A message of ``cls`` filled from JSON ``values``; ``stamp`` stands for "now".

    Raises:
        ConversionError: a value of the wrong kind or range, or a name that is not a field.
    """
    return _Filler(cls._type, stamp).message(cls, values, [])


__all__ = ["ConversionError", "cbor_values", "from_json", "json_values"]
