"""A message as one TCPROS frame in parts: its large byte arrays sent from the message itself.

A message is published over a socket as one frame, its length first, then what ``serialize``
writes. For a 10 MiB point cloud, serializing into one buffer is a 10 MiB copy into fresh
memory, whose page faults cost more than the copy, and whose release the allocator gives back
to the kernel: together about three times the kernel's own copy into the socket (bench/README.md,
"Against roscpp"). `frame_parts` instead serializes the small fields into small buffers and keeps
each large ``bytes`` value it meets (a ``uint8[]`` or ``char[]`` field of
`LARGE` bytes or more) as it is, a part of its own: the parts, in order, are the frame, and a
socket sends them with one ``sendmsg`` (`rosx.node.outgoing`). A ``bytes`` value cannot change,
so the frame is the message as it was when published, as a copy would be, whatever the caller
does to the message next; values of other types (``bytearray``, lists, numpy arrays) are
turned into ``bytes`` by the serializer first, as always.

Only types that have a variable-length ``uint8[]`` or ``char[]`` field, at any depth, are
serialized this way (`in_parts`); every other type is framed by its ``_frame`` as before.

Receiving, the same idea saves the subscriber a copy: a frame read whole into a buffer has its
large array copied out by the decoder. Where a type's first variable byte array is a field of
its own (an image's or a point cloud's ``data``), `array_locator` finds that array's length in
the frame's first bytes; a reader can then take the frame as a `FrameInParts`: the bytes before
the array, the array itself (read by the kernel straight into the ``bytes`` the message gets)
and the bytes after it. `decode_in_parts` makes the message of such a frame, the same message
the whole frame would decode to.
"""

from __future__ import annotations

import struct
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.message import Message
from rosx.msg.codec.wiretypes import BYTE_ARRAY_TYPES, PACK_CHARS, SIZES, TIME_CHARS

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.spec import Field, MsgSpec

    #: Finds a frame's large byte array: its payload's first bytes in, the offset of the
    #: array's length in the payload out (None: not among those bytes).
    Locator = Callable[[bytes | memoryview], int | None]

#: A byte array at least this large is a part of its own.
LARGE = 32 * 1024

_U32 = struct.Struct("<I")

#: Per class: whether its frames are made in parts (`in_parts`).
_known: dict[type, bool] = {}


def in_parts(cls: type) -> bool:
    """Whether messages of ``cls`` are framed in parts: a class of this codec with a
    variable-length ``uint8[]``/``char[]`` field, at any depth."""
    known = _known.get(cls)
    if known is None:
        spec = getattr(cls, "_spec", None)
        resolver = getattr(cls, "_resolver", None)
        known = (
            isinstance(cls, type)
            and issubclass(cls, Message)
            and spec is not None
            and resolver is not None
            and _has_byte_array(spec, resolver.lookup, set())
        )
        _known[cls] = known
    return known


def _has_byte_array(spec: MsgSpec, lookup: Callable[[str], MsgSpec], seen: set[str]) -> bool:
    for field in spec.fields:
        if field.base_type in BYTE_ARRAY_TYPES:
            if field.is_array and field.array_len is None:
                return True
        elif not field.is_builtin and field.base_type not in seen:
            seen.add(field.base_type)
            if _has_byte_array(lookup(field.base_type), lookup, seen):
                return True
    return False


class _Parts:
    """Where `frame_parts` serializes: small writes gather in a buffer, large ``bytes`` values
    become parts of their own."""

    __slots__ = ("parts", "small")

    def __init__(self) -> None:
        self.parts: list[bytes] = []
        self.small = bytearray(4)  # the frame's length, filled in at the end

    def write(self, data: Any) -> None:
        if data.__class__ is bytes and len(data) >= LARGE:
            if self.small:
                self.parts.append(bytes(self.small))
                self.small.clear()
            self.parts.append(data)
        else:
            self.small += data


def frame_parts(msg: Message) -> bytes | tuple[bytes, ...]:
    """``msg`` as one TCPROS frame: its bytes, or (a type of `in_parts` holding a large byte
    array) the frame's parts in order, the large arrays the message's own ``bytes``."""
    if not in_parts(msg.__class__):
        return msg._frame()
    buff = _Parts()
    msg.serialize(buff)
    parts, small = buff.parts, buff.small
    if not parts:  # no array large enough: one frame, as `_frame` makes it
        _U32.pack_into(small, 0, len(small) - 4)
        return bytes(small)
    if small:
        parts.append(bytes(small))
    parts[0] = _U32.pack(sum(len(part) for part in parts) - 4) + parts[0][4:]
    return tuple(parts)


class FrameInParts:
    """A frame received in three parts (see the module's docstring): ``head``, the payload up
    to and including the uint32 length of its large byte array; ``array``, the array's bytes;
    ``tail``, the rest of the payload. The length prefix is not part of it."""

    __slots__ = ("array", "head", "tail")

    def __init__(self, head: bytes, array: bytes, tail: bytes) -> None:
        self.head = head
        self.array = array
        self.tail = tail

    def __len__(self) -> int:
        return len(self.head) + len(self.array) + len(self.tail)

    def whole(self) -> bytes:
        """The payload in one piece (a copy)."""
        return b"".join((self.head, self.array, self.tail))


# A step of a locator's walk over the fields before the array (`_plan`): ("skip", n) fixed
# bytes; ("string",) a uint32 length and that many bytes; ("items", size) a uint32 count and
# that many items of ``size`` bytes; ("each", count or None, steps) that many items (None: a
# uint32 count first), each walked by ``steps``.
_Step = tuple[Any, ...]

#: Per class: its large array's name and the steps to it (`_array_field`).
_arrays: dict[type, tuple[str, tuple[_Step, ...]] | None] = {}


def _field_steps(field: Field, lookup: Callable[[str], MsgSpec]) -> list[_Step]:
    """The steps that walk over one field's bytes."""
    base = field.base_type
    if base in PACK_CHARS or base in TIME_CHARS:
        size = SIZES[PACK_CHARS[base]] if base in PACK_CHARS else 8
        if not field.is_array:
            return [("skip", size)]
        if field.array_len is not None:
            return [("skip", size * field.array_len)]
        return [("items", size)]
    item = [("string",)] if base == "string" else _message_steps(lookup(base), lookup)
    if not field.is_array:
        return item
    return [("each", field.array_len, tuple(item))]


def _message_steps(spec: MsgSpec, lookup: Callable[[str], MsgSpec]) -> list[_Step]:
    steps: list[_Step] = []
    for field in spec.fields:
        steps += _field_steps(field, lookup)
    return steps


def _walk(steps: tuple[_Step, ...], data: bytes | memoryview, at: int) -> int:
    """The offset after the fields ``steps`` walk, from ``at`` (IndexError: too few bytes)."""
    end = len(data)
    unpack = _U32.unpack_from
    for step in steps:
        kind = step[0]
        if kind == "skip":
            at += step[1]
        elif kind in {"string", "items"}:
            if at + 4 > end:
                raise IndexError(at)
            (count,) = unpack(data, at)
            at += 4 + count * (1 if kind == "string" else step[1])
        else:
            count = step[1]
            if count is None:
                if at + 4 > end:
                    raise IndexError(at)
                (count,) = unpack(data, at)
                at += 4
            for _ in range(count):
                at = _walk(step[2], data, at)
                if at > end:
                    raise IndexError(at)
    if at > end:
        raise IndexError(at)
    return at


def _array_field(cls: type) -> tuple[str, tuple[_Step, ...]] | None:
    """The name of ``cls``'s first variable ``uint8[]``/``char[]`` field, if it is a field of
    its own (not inside another message), and the steps over the fields before it."""
    if cls in _arrays:
        return _arrays[cls]
    found = _arrays[cls] = _find_array_field(cls) if in_parts(cls) else None
    return found


def _find_array_field(cls: type) -> tuple[str, tuple[_Step, ...]] | None:
    spec: MsgSpec = getattr(cls, "_spec")  # noqa: B009 - a generated class's, as `in_parts` found
    lookup = getattr(cls, "_resolver").lookup  # noqa: B009 - as the line above
    steps: list[_Step] = []
    for field in spec.fields:
        if field.base_type in BYTE_ARRAY_TYPES and field.is_array and field.array_len is None:
            return field.name, tuple(steps)
        if not field.is_builtin and _has_byte_array(lookup(field.base_type), lookup, set()):
            return None  # the first large array is inside another message
        steps += _field_steps(field, lookup)
    return None


def array_locator(cls: type) -> Locator | None:
    """How to find the large byte array of ``cls``'s frames (see the module's docstring);
    None for a type without one of its own."""
    found = _array_field(cls)
    if found is None:
        return None
    steps = found[1]

    def locate(head: bytes | memoryview) -> int | None:
        try:
            at = _walk(steps, head, 0)
        except IndexError:
            return None
        return at if at + 4 <= len(head) else None

    return locate


def decode_in_parts(
    fresh: Callable[[Message, bytes], Message], cls: type[Message], frame: FrameInParts
) -> Message:
    """The message of ``frame`` (of ``cls``, with a locator), decoded by ``fresh`` (a
    ``deserialize_fresh``): the small fields from the head and tail, the array as it was
    read, not copied."""
    found = _array_field(cls)
    assert found is not None
    # The small fields decode as a frame whose array is empty; the array is then set.
    msg = fresh(object.__new__(cls), b"".join((frame.head[:-4], bytes(4), frame.tail)))
    setattr(msg, found[0], frame.array)
    return msg


__all__ = [
    "LARGE",
    "FrameInParts",
    "array_locator",
    "decode_in_parts",
    "frame_parts",
    "in_parts",
]
