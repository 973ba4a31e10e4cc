"""TCPROS frames read back from a socket, for tests of what a stream sends, and a small one to
send; a clock for the stream that makes a series of frames a flood however loaded the machine;
a socket that holds a subscriber's read at the moment it has taken bytes and counted none; a
stream's condition that notes when its publisher waits."""

from __future__ import annotations

import socket
import struct
import threading
from typing import TYPE_CHECKING, Any

from tests.support.procs import wait_for

if TYPE_CHECKING:
    from rosx.node.outgoing import OutgoingStream


def twist_frame(number: int, size: int = 48) -> bytes:
    """A small frame (a Twist's size) whose body starts with ``number``."""
    return struct.pack("<II", size, number) + bytes(size - 4)


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


def assert_delivered(stream: OutgoingStream, peer: socket.socket, frames: list[bytes]) -> None:
    """The peer reads exactly ``frames``, whole and in order, and ``stream`` counts them all."""
    assert read_frames(peer, len(frames)) == frames
    wait_for(lambda: stream.frames_sent == len(frames), what="every frame counted")
    assert stream.bytes_sent == sum(len(frame) for frame in frames)


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


class HeldRead:
    """A connection's socket (put in place of ``stream.sock``) that holds one read: the first
    ``recv_into`` that starts once ``armed`` is set (at once, unless made unarmed) sets
    ``entered``, waits for ``published``, reads, sets ``taken`` and waits for ``go`` before it
    returns; the reading thread then holds bytes that no count has yet. Reads that started
    before pass through. ``shut`` is set when it is shut down (the subscription detached)."""

    def __init__(self, real: socket.socket, *, armed: bool = True) -> None:
        self.real = real
        self.armed = threading.Event()
        if armed:
            self.armed.set()
        self.entered = threading.Event()
        self.published = threading.Event()
        self.taken = threading.Event()
        self.go = threading.Event()
        self.shut = threading.Event()

    def recv_into(self, *args: Any) -> int:
        if not self.armed.is_set() or self.entered.is_set():
            return self.real.recv_into(*args)
        self.entered.set()
        self.published.wait(30)
        size = self.real.recv_into(*args)
        self.taken.set()
        self.go.wait(30)
        return size

    def shutdown(self, how: int) -> None:
        self.shut.set()
        self.real.shutdown(how)

    def release(self) -> None:
        """Let a held read go (at the end of a test, whatever happened)."""
        self.published.set()
        self.go.set()

    def __getattr__(self, name: str) -> Any:
        return getattr(self.real, name)


class NotedWait(threading.Condition):
    """A stream's condition (``_drained``) that notes when its publisher first waits."""

    def __init__(self, lock: Any) -> None:
        super().__init__(lock)
        self.waited = threading.Event()

    def wait(self, timeout: float | None = None) -> bool:
        self.waited.set()
        return super().wait(timeout)

    def until_waited(self, done: threading.Event) -> None:
        """Return once the publisher waits; fail if it finished (``done``) without waiting."""
        wait_for(lambda: self.waited.is_set() or done.is_set(), what="the publisher to wait")
        assert not done.is_set()
