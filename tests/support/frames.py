"""TCPROS frames read back from a socket, for tests of what a stream sends, and a clock for the
stream that makes a series of frames a flood however loaded the machine."""

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


class FloodClock:
    """A stream's clock (`rosx.node.outgoing._clock`, ns): each reading a microsecond after the
    last, so every series of frames is a flood, unless the test pauses it."""

    def __init__(self) -> None:
        self.now = 10**12

    def __call__(self) -> int:
        self.now += 1_000
        return self.now

    def pause(self, seconds: float) -> None:
        self.now += int(seconds * 1e9)
