"""Length-prefixed frames, the unit of every TCPROS stream (ROS wiki ROS/TCPROS).

On a TCPROS connection everything after the TCP handshake is a frame: a uint32 little-endian
length, then that many bytes. The first frame each side sends is its connection header; after
that, frames are serialized messages (topics) or requests (services).

`FrameReader` is incremental: `feed` it whatever the socket returned, in any chunking, then take
frames with `next_frame` (``None`` means more bytes are needed) or all complete ones at once with
`frames`. A length above the reader's `max_frame_size` raises `OversizedError` as soon as its
prefix arrives, so a peer that is out of sync cannot make this side gather what it claims.

Buffering keeps the common cases cheap: when a feed completes frames exactly, frames are slices
of the fed bytes; a small leftover is joined with the next feed (a copy no larger than twice the
new data); only a frame larger than the data arriving for it is gathered in a growing bytearray,
so building a 1 MiB frame from many small reads costs amortized linear time, never quadratic.
"""

from __future__ import annotations

import struct

from rosx.wire.errors import OversizedError, ProtocolError

_U32 = struct.Struct("<I")
_U32_MAX = 0xFFFFFFFF

#: ROS 1's roscpp drops a connection whose frame claims more than this (1e9 bytes).
DEFAULT_MAX_FRAME_SIZE = 1_000_000_000

#: A sensible bound for connection headers; full message definitions stay far below it.
DEFAULT_MAX_HEADER_SIZE = 4 * 1024 * 1024


def length_prefix(size: int) -> bytes:
    """The 4-byte prefix of a frame of `size` bytes (for sending prefix and payload separately)."""
    if not 0 <= size <= _U32_MAX:
        raise ProtocolError(f"frame of {size} bytes does not fit a uint32 length")
    return _U32.pack(size)


def frame(payload: bytes | bytearray | memoryview) -> bytes:
    """`payload` with its uint32 little-endian length prefix."""
    data = bytes(payload)
    return length_prefix(len(data)) + data


class FrameReader:
    """Splits a byte stream into length-prefixed frames, whatever the chunking of the input."""

    __slots__ = ("_buf", "_pos", "max_frame_size")

    def __init__(self, max_frame_size: int = DEFAULT_MAX_FRAME_SIZE) -> None:
        #: Largest payload accepted; may be changed between frames (e.g. after the header).
        self.max_frame_size = max_frame_size
        self._buf: bytes | bytearray = b""
        self._pos = 0

    @property
    def buffered(self) -> int:
        """Bytes received but not yet returned as frames."""
        return len(self._buf) - self._pos

    def feed(self, data: bytes | bytearray | memoryview) -> None:
        """Add bytes received from the peer. The reader keeps its own copy when it must."""
        if not data:
            return
        buf = self._buf
        pos = self._pos
        remaining = len(buf) - pos
        if remaining == 0:
            self._buf = data if type(data) is bytes else bytes(data)
        elif remaining <= len(data):
            # Joining costs at most twice the new data, and frames slice from bytes cheaply.
            with memoryview(buf) as view:
                self._buf = b"".join((view[pos:], data))
        elif isinstance(buf, bytearray):
            if pos:
                del buf[:pos]  # deleting a bytearray's head only advances its start
            buf += data
        else:
            # A frame is being gathered from reads smaller than itself: grow in place from now on.
            with memoryview(buf) as view:
                grown = bytearray(view[pos:])
            grown += data
            self._buf = grown
        self._pos = 0

    def next_frame(self) -> bytes | None:
        """Return the next complete frame's payload, or ``None`` until more bytes are fed.

        Raises:
            OversizedError: the next frame claims more than `max_frame_size` bytes.
        """
        buf = self._buf
        pos = self._pos
        if len(buf) - pos < 4:
            return None
        (size,) = _U32.unpack_from(buf, pos)
        if size > self.max_frame_size:
            raise OversizedError("frame", size, self.max_frame_size)
        start = pos + 4
        end = start + size
        if end > len(buf):
            return None
        self._pos = end
        if type(buf) is bytes:
            return buf[start:end]
        with memoryview(buf) as view:
            return view[start:end].tobytes()

    def pending(self) -> int:
        """The size of the frame whose length prefix is buffered but whose payload is not yet
        complete; 0 when there is none (or when it is oversized: `frames` raises for it)."""
        buf = self._buf
        pos = self._pos
        if len(buf) - pos < 4:
            return 0
        (size,) = _U32.unpack_from(buf, pos)
        if size > self.max_frame_size or pos + 4 + size <= len(buf):
            return 0
        return int(size)

    def take_pending(self, into: bytearray) -> int:
        """Move what is buffered of the `pending` frame's payload to the start of ``into``
        (which holds the whole payload); returns how many bytes that was. The reader is then
        empty: the caller reads the rest of the frame itself, e.g. with ``recv_into``."""
        with memoryview(self._buf) as view:
            head = view[self._pos + 4 :]
            count = len(head)
            into[:count] = head
            head.release()
        self._buf = b""
        self._pos = 0
        return count

    def frames(self) -> list[bytes]:
        """Return every complete frame buffered so far (possibly none), in order.

        Raises:
            OversizedError: the next frame claims more than `max_frame_size` bytes (raised only
                when no complete frame precedes it, so none is lost).
        """
        buf = self._buf
        out: list[bytes] = []
        if type(buf) is not bytes:
            try:
                while (payload := self.next_frame()) is not None:
                    out.append(payload)
            except OversizedError:
                if not out:
                    raise
            return out
        unpack_from = _U32.unpack_from
        limit = self.max_frame_size
        total = len(buf)
        pos = self._pos
        append = out.append
        while total - pos >= 4:
            (size,) = unpack_from(buf, pos)
            if size > limit:
                if out:
                    break
                self._pos = pos
                raise OversizedError("frame", size, limit)
            end = pos + 4 + size
            if end > total:
                break
            append(buf[pos + 4 : end])
            pos = end
        self._pos = pos
        return out
