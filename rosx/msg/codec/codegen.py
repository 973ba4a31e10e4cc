"""Build a message class from a spec: generated ``__init__``, ``serialize`` and ``deserialize``
(and ``_frame`` for types of a fixed size, `serializer.write_framer`).

As genpy does at build time, rosx writes Python source per message type and executes it once
(at first use of the type): constructors that fill defaults without loops, and a codec in the
ROS 1 wire format whose bytes are genpy's (see `serializer` and `deserializer`). The numpy
variants (``serialize_numpy``/``deserialize_numpy``) and the variant that decodes invalid UTF-8
with replacement characters are generated only when first needed. Every method of a generated
class that depends on its type is given here, to the class, so the base class
(`rosx.msg.codec.message.Message`) never calls up into its generator.
"""

from __future__ import annotations

import struct
from collections.abc import Callable
from typing import Any

from rosx.msg.codec import deserializer, serializer
from rosx.msg.codec.message import (
    DeserializationError,
    Message,
    SerializationError,
    assign_fields,
)
from rosx.msg.codec.rostime import Duration, Time
from rosx.msg.codec.source import Source, default_expression, python_name, python_names
from rosx.msg.codec.wiretypes import BYTE_ARRAY_TYPES, TIME_CHARS
from rosx.msg.spec import Field, MsgSpec

Lookup = Callable[[str], MsgSpec]
ClassOf = Callable[[str], type[Message]]

_SERIALIZE_ERRORS = (struct.error, TypeError, ValueError, AttributeError, OverflowError)


class Resolver:
    """How generated code finds the specs and classes of the types a message embeds."""

    def __init__(self, lookup: Lookup, class_of: ClassOf) -> None:
        self.lookup = lookup
        self.class_of = class_of


def build_message_class(
    spec: MsgSpec,
    md5sum: str,
    full_text: str,
    resolver: Resolver,
    methods: dict[str, Callable[..., Any]] | None = None,
) -> type:
    """The genpy-style class of ``spec``; the classes of embedded types must be buildable.

    ``methods`` are added to the class as they are (the class registry's pickling support).
    """
    src = Source(spec.full_name, _RUNTIME)
    _write_init(src, spec, resolver)
    serializer.write_serializer(src, spec, resolver.lookup, "serialize", numpy=False)
    deserializer.write_deserializer(
        src,
        spec,
        resolver.lookup,
        resolver.class_of,
        "deserialize",
        numpy=False,
        lossy=False,
        reuse=True,
    )
    framed = serializer.write_framer(src, spec, resolver.lookup)
    code = src.compile()
    namespace: dict[str, Any] = {
        "__slots__": python_names(spec),
        # genpy's module of the type (``geometry_msgs.msg._Twist``): what tracebacks print.
        "__module__": f"{spec.package}.msg._{spec.short_name}",
        "__qualname__": spec.short_name,
        "__doc__": f"The ROS 1 message type {spec.full_name}.",
        "_type": spec.full_name,
        "_md5sum": md5sum,
        "_full_text": full_text,
        "_has_header": spec.has_header,
        "_slot_types": [field.type for field in spec.fields],
        "_spec": spec,
        "_resolver": resolver,
        "_variants": {},
        "__init__": code["__init__"],
        "serialize": code["serialize"],
        "deserialize": code["deserialize"],
        "serialize_numpy": _serialize_numpy,
        "deserialize_numpy": _deserialize_numpy,
        "_check_types": _check_types,
        **(methods or {}),
    }
    if framed:
        namespace["_frame"] = code["_frame"]
    for constant in spec.constants:
        namespace[python_name(constant.name)] = constant.value
    return type(spec.short_name, (Message,), namespace)


def variant(cls: type[Message], name: str) -> Callable[..., Any]:
    """The method ``name`` of ``cls`` among those generated on first use.

    ``serialize_numpy`` and ``deserialize_numpy``; ``deserialize_fresh``, which builds every
    nested value anew and so also fills an instance made by ``object.__new__`` (the quickest
    way to read a message when nothing else holds it); ``deserialize_lossy`` and
    ``deserialize_numpy_lossy``, which replace undecodable UTF-8.
    """
    variants: dict[str, Callable[..., Any]] = cls._variants  # type: ignore[attr-defined]
    function = variants.get(name)
    if function is None:
        spec: MsgSpec = cls._spec  # type: ignore[assignment]
        resolver: Resolver = cls._resolver  # type: ignore[attr-defined]
        src = Source(f"{spec.full_name} {name}", _RUNTIME)
        numpy = "numpy" in name
        if name.startswith("serialize"):
            serializer.write_serializer(src, spec, resolver.lookup, name, numpy=numpy)
        else:
            lossy = "lossy" in name
            deserializer.write_deserializer(
                src,
                spec,
                resolver.lookup,
                resolver.class_of,
                name,
                numpy=numpy,
                lossy=lossy,
                reuse=False,
            )
        function = variants[name] = src.compile()[name]
    return function


def _serialize_numpy(self: Message, buff: Any, numpy: Any) -> None:
    """As ``serialize``, taking numeric arrays as numpy arrays."""
    variant(type(self), "serialize_numpy")(self, buff, numpy)


def _deserialize_numpy(self: Message, data: bytes, numpy: Any) -> Message:
    """As ``deserialize``, giving numeric arrays (not ``uint8[]``) as numpy arrays."""
    result: Message = variant(type(self), "deserialize_numpy")(self, data, numpy)
    return result


def _check_types(self: Message, exc: BaseException | None = None) -> None:
    """Raise `SerializationError` naming the first field that cannot be written."""
    from rosx.msg.codec.checks import find_problem  # noqa: PLC0415 - only on the error path

    problem = find_problem(self)
    if problem is not None:
        raise SerializationError(problem)
    if exc is not None:
        raise SerializationError(str(exc))


# -- constructors ---------------------------------------------------------------------------


def _write_init(src: Source, spec: MsgSpec, resolver: Resolver) -> None:
    defaults = [
        (attr, _default(src, field, resolver))
        for field, attr in zip(spec.fields, python_names(spec), strict=True)
    ]
    src.add(0, "def __init__(self, *args, **kwds):")
    src.add(1, "if args or kwds:")
    src.add(2, "_assign(self, args, kwds)")
    for attr, default in defaults:
        src.add(2, f"if self.{attr} is None: self.{attr} = {default}")
    if defaults:
        src.add(1, "else:")
        _write_defaults(src, spec, "self", resolver)


def _write_defaults(src: Source, spec: MsgSpec, obj: str, resolver: Resolver) -> None:
    """Set every field of ``obj`` to its default, nested messages and times built in place.

    Building nested values inline rather than through their constructors halves the cost of
    ``Twist()``, which rospy pays for every message it receives.
    """
    for field, attr in zip(spec.fields, python_names(spec), strict=True):
        base = field.base_type
        if field.is_array or default_expression(base) is not None:
            src.add(2, f"{obj}.{attr} = {_default(src, field, resolver)}")
        elif base in TIME_CHARS:
            value = src.local("t")
            src.add(2, f"{value} = {obj}.{attr} = _new({_time_class(base)})")
            src.add(2, f"{value}.secs = {value}.nsecs = 0")
        else:
            value = src.local("m")
            src.add(2, f"{value} = {obj}.{attr} = _new({src.bind(resolver.class_of(base), 'C')})")
            _write_defaults(src, resolver.lookup(base), value, resolver)


def _time_class(base: str) -> str:
    return "_Time" if base == "time" else "_Duration"


def _default(src: Source, field: Field, resolver: Resolver) -> str:
    """An expression giving a fresh default value of ``field``."""
    base, size = field.base_type, field.array_len
    literal = default_expression(base)
    if base in TIME_CHARS:
        element = f"_zero({_time_class(base)})"
    elif literal is not None:
        element = literal
    else:
        element = f"{src.bind(resolver.class_of(base), 'C')}()"
    if not field.is_array:
        return element
    if base in BYTE_ARRAY_TYPES:
        return "b''" if size is None else src.bind(bytes(size), "Z")
    if size is None:
        return "[]"
    if literal is not None:
        return f"[{element}] * {size}"
    return f"[{element} for _ in range({size})]"


# -- helpers the generated code calls -------------------------------------------------------


def _zero(cls: type[Time] | type[Duration]) -> Time | Duration:
    value = object.__new__(cls)
    value.secs = 0
    value.nsecs = 0
    return value


def _as_bytes(value: object) -> bytes:
    """A ``uint8[]``/``char[]`` value that is not bytes: a list/tuple of ints or a bytearray."""
    if value.__class__ is list or value.__class__ is tuple:
        items: list[int] = value  # type: ignore[assignment]
        return struct.pack(f"<{len(items)}B", *items)
    if isinstance(value, bytes | bytearray):
        return bytes(value)
    raise TypeError(f"a uint8[] value must be bytes or a list of ints, not {type(value).__name__}")


def _as_fixed_bytes(value: object, size: int) -> bytes | bytearray:
    if value.__class__ is list or value.__class__ is tuple:
        items: list[int] = value  # type: ignore[assignment]
        return struct.pack(f"<{size}B", *items)  # raises unless exactly `size` items
    if isinstance(value, bytes | bytearray):
        return value
    raise TypeError(f"a uint8[N] value must be bytes or a list of ints, not {type(value).__name__}")


_array_structs: dict[tuple[str, int], struct.Struct] = {}


def _array_struct(chars: str, count: int) -> struct.Struct:
    """The struct of ``count`` values of one type, kept for the sizes seen most recently."""
    key = (chars, count)
    packer = _array_structs.get(key)
    if packer is None:
        if len(_array_structs) >= 512:
            _array_structs.clear()
        packer = _array_structs[key] = struct.Struct(f"<{count}{chars}")
    return packer


def _check_length(value: Any, size: int) -> None:
    if len(value) != size:
        raise ValueError(f"expected {size} items but found {len(value)}")


def _short(available: int, needed: int) -> None:
    raise struct.error(f"needs {needed} bytes, but the message has {available}")


def _too_many(count: int) -> None:
    raise struct.error(f"holds {count} elements with no fields, more than are accepted")


def _serialization_error(msg: Message, exc: BaseException) -> Exception:
    from rosx.msg.codec.checks import serialization_error  # noqa: PLC0415 - only on the error path

    return serialization_error(msg, exc)


def _deserialization_error(msg: Message, data: bytes, exc: BaseException) -> Exception:
    return DeserializationError(f"cannot read {msg._type} from {len(data)} bytes: {exc}")


def _deserialize_unset(msg: Message, data: bytes, *numpy: Any) -> Message:
    """Deserialise into an instance whose nested fields were never set (made without __init__)."""
    name = "deserialize_numpy" if numpy else "deserialize_fresh"
    result: Message = variant(type(msg), name)(msg, data, *numpy)
    return result


_warned_types: set[str] = set()


def _decode_lossily(msg: Message, data: bytes, exc: UnicodeDecodeError, *numpy: Any) -> Message:
    """Deserialise again, replacing undecodable bytes; say so once per type, as genpy does."""
    if msg._type not in _warned_types:
        import logging  # noqa: PLC0415 - only when a message is undecodable

        _warned_types.add(msg._type)
        logging.getLogger("rosout").error(
            "Characters replaced when decoding message %s (will print only once): %s",
            msg._type,
            exc,
        )
    name = "deserialize_numpy_lossy" if numpy else "deserialize_lossy"
    result: Message = variant(type(msg), name)(msg, data, *numpy)
    return result


_RUNTIME: dict[str, Any] = {
    "_new": object.__new__,
    "_array_struct": _array_struct,
    "_StructError": struct.error,
    "_SerializeErrors": _SERIALIZE_ERRORS,
    "_Time": Time,
    "_Duration": Duration,
    "_zero": _zero,
    "_assign": assign_fields,
    "_as_bytes": _as_bytes,
    "_as_fixed_bytes": _as_fixed_bytes,
    "_check_length": _check_length,
    "_too_many": _too_many,
    "_short": _short,
    "_serialization_error": _serialization_error,
    "_deserialization_error": _deserialization_error,
    "_decode_lossily": _decode_lossily,
    "_deserialize_unset": _deserialize_unset,
}
