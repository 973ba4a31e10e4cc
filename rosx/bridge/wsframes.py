"""The frames a WebSocket server sends, as bytes (RFC 6455, section 5.2), without I/O.

A server's frames are never masked, and the bridges negotiate no extension, so a data frame is a
two-to-ten-byte header (FIN, the opcode, the payload's length) and the payload as it is. Writing
them here, not through the protocol object of `websockets`, lets any thread frame a message for
a client (the protocol object is the event loop's), and lets a large payload go to the socket
as it is, beside its header, rather than copied into one buffer with it.
"""

from __future__ import annotations

import struct
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from rosx.bridge.ops import Frame, Pieces

TEXT = 0x1
BINARY = 0x2
CLOSE = 0x8
#: A close frame's status code for a message over the size limit (RFC 6455, 7.4.1).
MESSAGE_TOO_BIG = 1009
#: Payloads up to this size are joined to their header (one buffer is cheaper than two).
JOIN_BELOW = 4096

_MEDIUM = struct.Struct("!BBH")
_LARGE = struct.Struct("!BBQ")


def header(opcode: int, length: int) -> bytes:
    """The header of a final, unmasked frame of ``opcode`` carrying ``length`` bytes."""
    first = 0x80 | opcode
    if length < 126:
        return bytes((first, length))
    if length < 1 << 16:
        return _MEDIUM.pack(first, 126, length)
    return _LARGE.pack(first, 127, length)


def wire(frame: Frame | Pieces) -> list[bytes]:
    """``frame`` as the buffers to write, in order: text for a `str`, binary for `bytes` or a
    tuple of pieces (written one after the other, never joined)."""
    if isinstance(frame, str):
        data = frame.encode()
        if len(data) < JOIN_BELOW:
            return [header(TEXT, len(data)) + data]
        return [header(TEXT, len(data)), data]
    if isinstance(frame, bytes):
        if len(frame) < JOIN_BELOW:
            return [header(BINARY, len(frame)) + frame]
        return [header(BINARY, len(frame)), frame]
    length = sum(map(len, frame))
    if length < JOIN_BELOW:
        return [header(BINARY, length) + b"".join(frame)]
    return [header(BINARY, length), *frame]


def closes_with(data: bytes, code: int) -> bool:
    """Whether ``data`` (bytes a server writes) starts with a close frame of status ``code``."""
    return len(data) >= 4 and data[0] == 0x80 | CLOSE and int.from_bytes(data[2:4], "big") == code


def close_reason(data: bytes) -> str:
    """The reason text of the close frame ``data`` starts with (a server's: never masked)."""
    return data[4 : 2 + (data[1] & 0x7F)].decode(errors="replace")


__all__ = [
    "BINARY",
    "CLOSE",
    "MESSAGE_TOO_BIG",
    "TEXT",
    "close_reason",
    "closes_with",
    "header",
    "wire",
]
