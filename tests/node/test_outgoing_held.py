"""A publisher's stream holding frames back while its Unix peer is behind (`rosx.node.outgoing`):
the peer gets the same bytes in the same order, a frame after a pause or to a peer that has read
everything goes at once, nothing held is lost (the loop writes it, `close` writes it), and a
bounded queue drops nothing it would not have dropped.

The stream's clock is replaced by one the test moves, so a run of frames and a pause are what the
test says they are, however loaded the machine."""

from __future__ import annotations

import fcntl
import socket
import struct
import sys
import termios
from collections.abc import Iterator
from typing import Any

import pytest

from rosx.node import outgoing, unixros
from rosx.node.outgoing import HOLD_RUN, OutgoingStream
from rosx.transport.loop_thread import LoopThread
from tests.support.frames import FloodClock as Clock
from tests.support.frames import assert_delivered, read_frames, twist_frame
from tests.support.procs import wait_for

pytestmark = pytest.mark.skipif(
    not sys.platform.startswith("linux"), reason="a Unix socket's unread bytes: Linux only"
)


@pytest.fixture
def pair() -> Iterator[tuple[socket.socket, socket.socket]]:
    mine, peer = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
    yield mine, peer
    peer.close()


def stream_of(mine: socket.socket, io: LoopThread, queue_size: int | None = 0) -> OutgoingStream:
    unread = unixros.unread_probe(mine)
    assert unread is not None
    return OutgoingStream(mine, io, queue_size, unread=unread)


def send_flood(stream: OutgoingStream, count: int) -> list[bytes]:
    """Send ``count`` small frames (numbered from 0) as a flood; returns them."""
    sent = [twist_frame(n) for n in range(count)]
    for item in sent:
        stream.send(item)
    return sent


def test_a_flood_to_a_peer_behind_is_held_then_arrives_whole_and_in_order(
    io: LoopThread,
    pair: tuple[socket.socket, socket.socket],
    clock: Clock,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(outgoing, "HOLD_TICK", 0.3)
    mine, peer = pair
    stream = stream_of(mine, io)
    sent = [twist_frame(n) for n in range(40)]
    for item in sent:
        stream.send(item)
    # The peer has read nothing: after the first run of frames, the rest wait together,
    # though the socket has room for them.
    assert stream.queued == len(sent) - HOLD_RUN
    # Nothing more is published: the loop writes what is held.
    assert_delivered(stream, peer, sent)
    stream.close()


def test_frames_to_a_peer_that_has_read_everything_go_at_once(
    io: LoopThread, pair: tuple[socket.socket, socket.socket], clock: Clock
) -> None:
    """A ping-pong, or a reader that keeps up with a flood: never held."""
    mine, peer = pair
    stream = stream_of(mine, io)
    for number in range(100):
        item = twist_frame(number)
        stream.send(item)
        assert stream.queued == 0
        assert read_frames(peer, 1) == [item]
    stream.close()


def test_a_frame_after_a_pause_goes_at_once_with_what_was_held(
    io: LoopThread,
    pair: tuple[socket.socket, socket.socket],
    clock: Clock,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(outgoing, "HOLD_TICK", 30.0)  # only the pause writes them
    mine, peer = pair
    stream = stream_of(mine, io)
    sent = send_flood(stream, 30)
    assert stream.queued
    clock.pause(0.001)
    sent.append(twist_frame(30))
    stream.send(sent[-1])
    assert stream.queued == 0
    assert read_frames(peer, len(sent)) == sent
    stream.close()


@pytest.mark.parametrize(
    "in_parts",
    [
        pytest.param((struct.pack("<II", 8000, 30), bytes(7996)), id="large, as an image's"),
        pytest.param((twist_frame(30)[:8], twist_frame(30)[8:]), id="small"),
    ],
)
def test_a_frame_in_parts_is_never_held_and_takes_the_held_ones_along(
    io: LoopThread,
    pair: tuple[socket.socket, socket.socket],
    clock: Clock,
    monkeypatch: pytest.MonkeyPatch,
    in_parts: tuple[bytes, ...],
) -> None:
    monkeypatch.setattr(outgoing, "HOLD_TICK", 30.0)
    mine, peer = pair
    stream = stream_of(mine, io)
    sent: list[bytes | tuple[bytes, ...]] = [twist_frame(n) for n in range(30)]
    for item in sent:
        stream.send(item)
    assert stream.holding
    sent.append(in_parts)
    stream.send(in_parts)
    assert (stream.holding, stream.queued) == (False, 0)
    # The flood goes on: holding would start again with the 16th frame of the new run (46),
    # but not with a frame in parts; it starts later, and each frame in parts ends it.
    held_again = 0
    for number in range(31, 80):
        split = number in (46, 60, 70)
        item = (twist_frame(number)[:8], bytes(44)) if split else twist_frame(number)
        sent.append(item)
        stream.send(item)
        if split:
            assert (stream.holding, stream.queued) == (False, 0)
        held_again += stream.holding
    assert held_again
    stream.close()
    expected = [item if isinstance(item, bytes) else b"".join(item) for item in sent]
    assert read_frames(peer, len(sent)) == expected


def test_closing_writes_what_is_held(
    io: LoopThread,
    pair: tuple[socket.socket, socket.socket],
    clock: Clock,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(outgoing, "HOLD_TICK", 30.0)
    mine, peer = pair
    stream = stream_of(mine, io)
    sent = [twist_frame(n) for n in range(50)]
    for item in sent:
        stream.send(item)
    assert stream.queued
    stream.close()
    assert read_frames(peer, len(sent)) == sent
    assert peer.recv(10) == b""  # then the end of the stream


def test_a_bounded_queue_holds_no_more_than_its_size_and_drops_nothing_for_it(
    io: LoopThread,
    pair: tuple[socket.socket, socket.socket],
    clock: Clock,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(outgoing, "HOLD_TICK", 30.0)
    mine, peer = pair
    stream = stream_of(mine, io, queue_size=5)
    sent = [twist_frame(n) for n in range(60)]
    for item in sent:
        stream.send(item)
        assert stream.queued <= 5
    assert stream.dropped == 0  # the socket had room for every frame
    clock.pause(0.001)
    sent.append(twist_frame(60))
    stream.send(sent[-1])
    assert read_frames(peer, len(sent)) == sent
    stream.close()


def test_a_full_socket_behind_held_frames_loses_nothing(
    io: LoopThread, pair: tuple[socket.socket, socket.socket], clock: Clock
) -> None:
    """Held frames that the socket cannot take wait as any frames it cannot take: the loop
    writes them once the peer reads."""
    mine, peer = pair
    mine.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, 16 * 1024)  # fills at once
    stream = stream_of(mine, io, queue_size=0)
    sent = [twist_frame(n, 1000 + n) for n in range(300)]
    for item in sent:
        stream.send(item)
    assert read_frames(peer, len(sent)) == sent
    wait_for(lambda: stream.queued == 0, what="the queue to empty")
    stream.close()


def test_flush_writes_what_is_held_at_once_and_holding_starts_afresh(
    io: LoopThread,
    pair: tuple[socket.socket, socket.socket],
    clock: Clock,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """An action server flushes its feedback before it publishes the goal's result, which
    travels on another stream: the held feedback must be in the socket by then."""
    monkeypatch.setattr(outgoing, "HOLD_TICK", 30.0)  # only the flush writes them
    mine, peer = pair
    stream = stream_of(mine, io)
    sent = send_flood(stream, 30)
    assert stream.queued == len(sent) - HOLD_RUN
    stream.flush()
    assert stream.queued == 0
    waiting = fcntl.ioctl(peer.fileno(), termios.FIONREAD, b"\0\0\0\0")
    assert int.from_bytes(waiting, "little") == sum(len(item) for item in sent)
    assert read_frames(peer, len(sent)) == sent
    # The next frames are a new run: the first HOLD_RUN of them go at once.
    later = [twist_frame(n) for n in range(100, 100 + HOLD_RUN)]
    for item in later:
        stream.send(item)
        assert stream.queued == 0
    assert read_frames(peer, len(later)) == later
    stream.close()


class ShortWrite(socket.socket):
    """A stream's socket whose next gathered write, once ``short`` is set, takes ten bytes."""

    short = False

    def sendmsg(self, buffers: Any, *args: Any) -> int:
        if self.short:
            self.short = False
            return super().sendmsg([b"".join(buffers)[:10]])
        return super().sendmsg(buffers, *args)


def test_the_loops_write_leaves_held_frames_to_the_holding(
    io: LoopThread,
    pair: tuple[socket.socket, socket.socket],
    clock: Clock,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The loop may still wait for room from before a flood's frames were held (the socket
    was full, then the publisher's own write emptied the queue): when the room comes, a part
    of a held frame written then would be written again with the held frames."""
    monkeypatch.setattr(outgoing, "HOLD_TICK", 30.0)
    plain, peer = pair
    mine = ShortWrite(plain.family, plain.type, fileno=plain.detach())
    stream = stream_of(mine, io)
    sent = send_flood(stream, 30)
    assert stream.holding
    mine.short = True
    stream._on_writable()  # as the loop calls it when the socket is writable
    sent += [twist_frame(n) for n in range(30, 40)]
    for item in sent[30:]:
        stream.send(item)
    clock.pause(0.001)
    sent.append(twist_frame(40))
    stream.send(sent[-1])
    assert read_frames(peer, len(sent)) == sent
    stream.close()
    mine.close()
