"""TCPROS connection headers, as specified on the ROS wiki page ROS/Connection Header.

A header is a block: a uint32 little-endian length of everything that follows, then fields, each a
uint32 little-endian length and the UTF-8 text ``name=value``. The name ends at the first ``=``;
the value may contain more of them. Both ends of a topic or service connection send one header
before any data; a side that refuses the connection answers with a header holding only ``error``.

`encode_header` returns the whole block, length prefix included, ready to send. `decode_header`
takes the block *without* its length prefix: the payload that `framing.FrameReader` yields for the
first frame of a connection. ROS 1 itself sorts fields by name; `encode_header` keeps the order it
is given, and the handshake builders in `tcpros` and `rosrpc` give them sorted.
"""

from __future__ import annotations

import struct

from rosx.record import Record
from rosx.wire.errors import ProtocolError

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Mapping

_U32 = struct.Struct("<I")
_U32_MAX = 0xFFFFFFFF

#: The field that carries a refusal; a refusing side sends a header with only this field.
ERROR_FIELD = "error"


def encode_header(fields: Mapping[str, str]) -> bytes:
    """Encode `fields` as a connection header block, length prefix included, in the given order.

    Raises:
        ProtocolError: a field name is empty or contains ``=`` (the peer could not split it), or
            the block would not fit a uint32 length.
    """
    pack = _U32.pack
    parts: list[bytes] = []
    for name, value in fields.items():
        if not name or "=" in name:
            raise ProtocolError(
                f"connection header field name {name!r} is invalid: names must be non-empty "
                "and must not contain '='"
            )
        entry = f"{name}={value}".encode()
        parts.append(pack(len(entry)))
        parts.append(entry)
    body = b"".join(parts)
    if len(body) > _U32_MAX:
        raise ProtocolError(f"connection header of {len(body)} bytes does not fit a uint32 length")
    return pack(len(body)) + body


def decode_header(block: bytes | bytearray | memoryview) -> dict[str, str]:
    """Decode a connection header block given without its uint32 length prefix.

    Fields come back in the order they were sent; a repeated name keeps its last value, as in
    ROS 1.

    Raises:
        ProtocolError: a field length runs past the end of the block, the block ends inside a
            field length, a field is empty, has no ``=``, or is not UTF-8.
    """
    data = bytes(block)
    end = len(data)
    unpack_from = _U32.unpack_from
    fields: dict[str, str] = {}
    pos = 0
    index = 0
    while pos < end:
        if end - pos < 4:
            raise ProtocolError(
                f"connection header ends inside the length of field {index} "
                f"({end - pos} of 4 bytes present)"
            )
        (size,) = unpack_from(data, pos)
        pos += 4
        if size == 0:
            raise ProtocolError(f"connection header field {index} is empty (length 0)")
        if size > end - pos:
            raise ProtocolError(
                f"connection header field {index} claims {size} bytes but only "
                f"{end - pos} remain in the header"
            )
        raw = data[pos : pos + size]
        pos += size
        try:
            line = raw.decode()
        except UnicodeDecodeError as exc:
            raise ProtocolError(
                f"connection header field {index} is not UTF-8 ({exc.reason} at byte {exc.start})"
            ) from None
        name, sep, value = line.partition("=")
        if not sep:
            raise ProtocolError(
                f"connection header field {index} has no '=' between name and value: {line!r}"
            )
        fields[name] = value
        index += 1
    return fields


class Refused(Record):
    """A handshake that failed: `reason` is ROS 1's text for why.

    ``by_peer`` is true when the other side sent the refusal (an ``error`` field in its header);
    otherwise this side refuses, and sends `header` to say so before closing.
    """

    __match_args__ = ("reason", "by_peer")
    __slots__ = __match_args__
    reason: str
    by_peer: bool

    def __init__(self, reason: str, by_peer: bool = False) -> None:
        super().__init__(reason=reason, by_peer=by_peer)

    @property
    def header(self) -> dict[str, str]:
        """The fields of the header that carries this refusal: only ``error``."""
        return {ERROR_FIELD: self.reason}
