"""How each ROS 1 built-in type is laid out on the wire, as `struct` format characters.

ROS 1 serialisation (wiki ROS/Message_serialization) is little-endian without padding; ``bool``
is one byte, ``char`` an unsigned and ``byte`` a signed byte (their deprecated meanings),
``time`` two uint32 and ``duration`` two int32 (seconds, nanoseconds). Strings and arrays of
variable length carry a uint32 count first.
"""

from __future__ import annotations

#: The `struct` character each fixed-size scalar type is packed with.
PACK_CHARS: dict[str, str] = {
    "bool": "B",
    "int8": "b",
    "uint8": "B",
    "byte": "b",
    "char": "B",
    "int16": "h",
    "uint16": "H",
    "int32": "i",
    "uint32": "I",
    "int64": "q",
    "uint64": "Q",
    "float32": "f",
    "float64": "d",
}

#: Unpacking differs only for bool: genpy turns the byte into a Python bool, as ``?`` does.
UNPACK_CHARS: dict[str, str] = {**PACK_CHARS, "bool": "?"}

#: numpy dtypes of the numeric types, little-endian as on the wire.
NUMPY_DTYPES: dict[str, str] = {
    "bool": "bool",
    "int8": "<i1",
    "uint8": "<u1",
    "byte": "<i1",
    "char": "<u1",
    "int16": "<i2",
    "uint16": "<u2",
    "int32": "<i4",
    "uint32": "<u4",
    "int64": "<i8",
    "uint64": "<u8",
    "float32": "<f4",
    "float64": "<f8",
}

SIZES: dict[str, int] = {
    "B": 1,
    "b": 1,
    "?": 1,
    "h": 2,
    "H": 2,
    "i": 4,
    "I": 4,
    "q": 8,
    "Q": 8,
    "f": 4,
    "d": 8,
}

#: ``time`` and ``duration``: two 32-bit fields each.
TIME_CHARS: dict[str, str] = {"time": "I", "duration": "i"}

#: Arrays of these element types are bytes objects in Python, not lists of ints.
BYTE_ARRAY_TYPES = frozenset({"uint8", "char"})

INTEGER_RANGES: dict[str, tuple[int, int]] = {
    "int8": (-(1 << 7), (1 << 7) - 1),
    "byte": (-(1 << 7), (1 << 7) - 1),
    "uint8": (0, (1 << 8) - 1),
    "char": (0, (1 << 8) - 1),
    "int16": (-(1 << 15), (1 << 15) - 1),
    "uint16": (0, (1 << 16) - 1),
    "int32": (-(1 << 31), (1 << 31) - 1),
    "uint32": (0, (1 << 32) - 1),
    "int64": (-(1 << 63), (1 << 63) - 1),
    "uint64": (0, (1 << 64) - 1),
}
