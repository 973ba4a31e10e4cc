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
"""

from __future__ import annotations

import struct
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.message import Message
from rosx.msg.codec.wiretypes import BYTE_ARRAY_TYPES

if TYPE_CHECKING:
    from collections.abc import Callable

    from rosx.msg.spec import MsgSpec

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


__all__ = ["LARGE", "frame_parts", "in_parts"]
