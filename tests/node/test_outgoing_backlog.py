"""A publisher's stream ahead of its peer (`rosx.node.outgoing`): while the socket has no room
the frames wait, and `send` does not offer the waiting queue to the socket (one gathered
``sendmsg`` refused every few frames was most of a publisher's time next to a slow roscpp
subscriber); once the peer reads, every frame arrives, whole and in order. A bounded queue
still offers the socket its queue before it drops a frame (`test_outgoing_parts.py`)."""

from __future__ import annotations

import socket
from collections.abc import Iterator
from typing import Any

import pytest

from rosx.node.outgoing import FLUSH_EVERY, OutgoingStream
from rosx.transport.loop_thread import LoopThread
from tests.support.frames import read_frames, twist_frame
from tests.support.procs import wait_for


class CountingSocket(socket.socket):
    """A stream's socket that counts the gathered writes it is offered."""

    offers = 0

    def sendmsg(self, *args: Any, **kwargs: Any) -> int:
        self.offers += 1
        return super().sendmsg(*args, **kwargs)


@pytest.fixture
def pair() -> Iterator[tuple[CountingSocket, socket.socket]]:
    mine, peer = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
    counting = CountingSocket(mine.family, mine.type, fileno=mine.detach())
    yield counting, peer
    counting.close()
    peer.close()


def test_a_full_socket_is_not_offered_the_queue_and_the_peer_gets_every_frame_in_order(
    io: LoopThread, pair: tuple[CountingSocket, socket.socket]
) -> None:
    mine, peer = pair
    stream = OutgoingStream(mine, io, 0)  # unbounded: nothing dropped
    sent: list[bytes] = []
    while not stream.queued:  # the peer reads nothing: the kernel's buffer fills
        sent.append(twist_frame(len(sent)))
        stream.send(sent[-1])
    for _ in range(20 * FLUSH_EVERY):
        sent.append(twist_frame(len(sent)))
        stream.send(sent[-1])
    assert mine.offers == 0  # before: one gathered sendmsg, refused, every FLUSH_EVERY frames
    assert stream.queued > 20 * FLUSH_EVERY and not stream.dropped
    assert read_frames(peer, len(sent)) == sent
    wait_for(lambda: stream.frames_sent == len(sent), what="the stream's count")
    stream.close()
