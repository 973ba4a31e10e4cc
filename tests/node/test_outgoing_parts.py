"""A publisher's stream given frames in parts (`rosx.node.outgoing`): the peer reads the same
bytes as whole frames would give it, in order, and a bounded queue drops whole frames only."""

from __future__ import annotations

import socket
import struct
import threading
from collections.abc import Iterator

import pytest

from rosx.node.outgoing import OutgoingStream, frame_size
from rosx.transport.loop_thread import LoopThread
from tests.support.frames import read_frames
from tests.support.procs import wait_for


@pytest.fixture
def pair() -> Iterator[tuple[socket.socket, socket.socket]]:
    mine, peer = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
    mine.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, 64 * 1024)  # fills at once
    yield mine, peer
    peer.close()


def frame(number: int, size: int, *, parts: bool) -> bytes | tuple[bytes, ...]:
    """A frame of ``size`` bytes after its length: a small head naming ``number``, then a large
    body (a part of its own when ``parts``), then a small tail."""
    tail = b"end!"
    head = struct.pack("<II", size, number)
    body = bytes([number % 251]) * (size - 4 - len(tail))
    return (head, body, tail) if parts else head + body + tail


def whole(value: bytes | tuple[bytes, ...]) -> bytes:
    return value if isinstance(value, bytes) else b"".join(value)


def test_frames_in_parts_reach_the_peer_as_the_same_bytes_in_order(
    io: LoopThread, pair: tuple[socket.socket, socket.socket]
) -> None:
    mine, peer = pair
    stream = OutgoingStream(mine, io, 0)  # unbounded: nothing dropped
    sent = [frame(n, 100_000 + 7 * n, parts=n % 2 == 0) for n in range(12)]
    sent.insert(3, b"\x04\x00\x00\x00tiny")
    for item in sent:
        stream.send(item)
    assert stream.queued  # the peer has read nothing: most wait
    frames = read_frames(peer, len(sent))
    assert frames == [whole(item) for item in sent]
    wait_for(lambda: stream.frames_sent == len(sent))
    assert stream.bytes_sent == sum(frame_size(item) for item in sent)
    stream.close()


def test_a_bounded_queue_drops_whole_frames_never_the_one_on_the_wire(
    io: LoopThread, pair: tuple[socket.socket, socket.socket]
) -> None:
    mine, peer = pair
    stream = OutgoingStream(mine, io, 2)
    sent = [frame(n, 300_000, parts=True) for n in range(10)]
    for item in sent:
        stream.send(item)
    assert stream.dropped > 0
    kept = len(sent) - stream.dropped
    frames = read_frames(peer, kept)
    numbers = [struct.unpack_from("<I", got, 4)[0] for got in frames]
    assert numbers == sorted(numbers)
    assert numbers[0] == 0  # the first was on the wire when the others came
    assert numbers[-2:] == [8, 9]  # the newest are kept
    assert frames == [whole(sent[n]) for n in numbers]
    stream.close()


def test_an_unbounded_blocking_queue_waits_and_loses_nothing(
    io: LoopThread, pair: tuple[socket.socket, socket.socket]
) -> None:
    mine, peer = pair
    stream = OutgoingStream(mine, io, None)  # queue_size=None: the publisher waits
    sent = [frame(n, 1 << 20, parts=n != 3) for n in range(8)]
    done = threading.Event()

    def publish() -> None:
        for item in sent:
            stream.send(item)
        done.set()

    thread = threading.Thread(target=publish)
    thread.start()
    assert not done.wait(0.2)  # 8 MiB: more than may wait
    frames = read_frames(peer, len(sent))
    thread.join(10)
    assert done.is_set()
    assert frames == [whole(item) for item in sent]
    stream.close()
