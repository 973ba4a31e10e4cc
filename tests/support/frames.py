"""TCPROS frames read back from a socket, for tests of what a stream sends."""

from __future__ import annotations

import socket


def read_frames(peer: socket.socket, count: int) -> list[bytes]:
    """``count`` whole frames from the stream (length prefix included); fails if more came."""
    data = bytearray()
    frames: list[bytes] = []
    peer.settimeout(10)
    while len(frames) < count:
        while len(data) >= 4 and len(data) >= 4 + int.from_bytes(data[:4], "little"):
            size = 4 + int.from_bytes(data[:4], "little")
            frames.append(bytes(data[:size]))
            del data[:size]
        if len(frames) < count:
            chunk = peer.recv(1 << 20)
            assert chunk, "the stream ended"
            data += chunk
    assert not data
    return frames
