"""A publisher's stream over TCP holding frames back while its kernel holds bytes back
(`rosx.node.outgoing.unsent_probe`): the peer's window is full, or Nagle's algorithm waits for
an acknowledgement. The peer gets the same bytes in the same order; a frame after a pause goes
at once with what was held; frames to a peer that reads them as they come are never held. A
publication holds a flood over TCP only when its queue drops nothing. A publisher whose queue
neither drops nor grows without end (``queue_size=None``) is paced while its messages are small:
it waits for a peer that is behind once about twice `PACED_BYTES` are written and unread.

The stream's clock is replaced by one the test moves (`FloodClock`), so a run of frames and a
pause are what the test says they are, however loaded the machine."""

from __future__ import annotations

import socket
import sys
import threading
from collections.abc import Callable, Iterator
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node, local, outgoing, unixros
from rosx.node.outgoing import (
    HIGH_WATER,
    HOLD_RUN,
    HOLD_SIZE,
    PACED_BYTES,
    OutgoingStream,
    unsent_probe,
)
from rosx.node.publication import SubscriberLink
from rosx.transport.loop_thread import LoopThread
from tests.support.frames import FloodClock as Clock
from tests.support.frames import NotedWait, assert_delivered, read_frames, twist_frame
from tests.support.procs import wait_for

Twist = get_message_class("geometry_msgs/Twist")

pytestmark = pytest.mark.skipif(
    not sys.platform.startswith("linux"), reason="TCP_INFO's unsent bytes: Linux only"
)


@pytest.fixture
def pair() -> Iterator[tuple[socket.socket, socket.socket]]:
    """A loopback TCP connection whose reading end has a small buffer (a small window)."""
    with socket.create_server(("127.0.0.1", 0)) as listener:
        listener.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)  # the accepted end's
        mine = socket.create_connection(listener.getsockname())
        peer, _ = listener.accept()
    yield mine, peer
    mine.close()
    peer.close()


def test_the_probe_says_what_the_kernel_has_not_sent(
    pair: tuple[socket.socket, socket.socket],
) -> None:
    mine, peer = pair
    unsent = unsent_probe(mine)
    assert unsent is not None
    assert unsent() == 0
    mine.setblocking(False)
    written = 0
    while not unsent() and written < 1 << 20:  # the peer reads nothing: its window fills
        written += mine.send(bytes(1000))
    assert 0 < unsent() < written
    received = 0
    while received < written:  # it reads: the kernel sends what waited
        received += len(peer.recv(1 << 16))
    wait_for(lambda: unsent() == 0, what="every byte sent")
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as local:
        assert unsent_probe(local) is None


def test_a_flood_behind_bytes_the_kernel_holds_is_held_then_arrives_whole_and_in_order(
    io: LoopThread,
    pair: tuple[socket.socket, socket.socket],
    clock: Clock,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(outgoing, "HOLD_TICK", 30.0)  # only the pause writes them
    mine, peer = pair
    unsent = unsent_probe(mine)
    assert unsent is not None
    stream = OutgoingStream(mine, io, 0, unread=unsent)
    sent: list[bytes] = []
    while not unsent() and len(sent) < 1000:  # frames a pause apart, none read: never held
        sent.append(twist_frame(len(sent)))
        stream.send(sent[-1])
        assert (stream.holding, stream.queued) == (False, 0)
        clock.pause(0.001)
    assert unsent()  # the peer's window is full, or an acknowledgement is awaited
    flood = [twist_frame(number) for number in range(len(sent), len(sent) + 40)]
    for item in flood:
        stream.send(item)
    # The first HOLD_RUN frames of the run go to the kernel, which keeps them with the rest;
    # the others wait together in the stream, though the socket has room for them.
    assert (stream.holding, stream.queued) == (True, len(flood) - HOLD_RUN)
    clock.pause(0.001)
    last = twist_frame(len(sent) + len(flood))
    stream.send(last)  # a pause: what was held goes, then this frame
    assert (stream.holding, stream.queued) == (False, 0)
    assert_delivered(stream, peer, [*sent, *flood, last])
    stream.close()


def test_frames_to_a_peer_that_reads_them_as_they_come_go_at_once(
    io: LoopThread, pair: tuple[socket.socket, socket.socket], clock: Clock
) -> None:
    """As for a subscriber that asked for ``tcp_nodelay``: nothing waits in the kernel."""
    mine, peer = pair
    mine.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    stream = OutgoingStream(mine, io, 0, unread=unsent_probe(mine))
    for number in range(100):
        item = twist_frame(number)
        stream.send(item)
        assert (stream.holding, stream.queued) == (False, 0)
        assert read_frames(peer, 1) == [item]
    stream.close()


def linked_over_tcp(
    make_node: Callable[..., Node],
    monkeypatch: pytest.MonkeyPatch,
    callback: Callable[[Any], None],
    queue_size: int | None,
) -> tuple[Any, SubscriberLink]:
    """A Twist publisher with ``queue_size`` and a subscriber (unbounded) calling ``callback``,
    in two nodes linked over TCP: the publisher and its one link."""
    monkeypatch.setattr(local, "ENABLED", False)
    monkeypatch.setattr(unixros, "ENABLED", False)
    talker, listener = make_node("tcp_talker"), make_node("tcp_listener")
    sub = listener.subscribe("/flood", Twist, callback, queue_size=0)
    pub = talker.advertise("/flood", Twist, queue_size=queue_size)
    wait_for(lambda: pub.get_num_connections() == 1 and sub.get_num_connections() == 1)
    (link,) = talker.publications["/flood"].links
    return pub, link


@pytest.mark.parametrize(
    ("queue_size", "held"),
    [(None, True), (0, True), (100, False)],
    ids=["queue None", "unbounded", "queue 100"],
)
def test_a_publication_holds_a_flood_over_tcp_unless_its_queue_drops(
    make_node: Callable[..., Node],
    monkeypatch: pytest.MonkeyPatch,
    clock: Clock,
    queue_size: int | None,
    held: bool,
) -> None:
    """A subscriber stuck in its callback reads nothing: its window fills, then the kernel
    holds bytes back. A bounded queue is never held back over TCP: in batches a flood
    fills the kernel's buffers sooner and drops what one message a send delivered."""
    go_on = threading.Event()
    got: list[int] = []

    def stuck(msg: Any) -> None:
        go_on.wait(30)
        got.append(int(msg.linear.x))

    pub, link = linked_over_tcp(make_node, monkeypatch, stuck, queue_size)
    sent = 0
    try:
        while not link.stream.holding and sent < 20_000:
            msg = Twist()
            msg.linear.x = float(sent)
            pub.publish(msg)
            sent += 1
        assert link.stream.holding is held
    finally:
        go_on.set()
    if held:
        wait_for(lambda: len(got) == sent, what="every message")
        assert got == list(range(sent))


def test_a_paced_publisher_waits_for_a_peer_that_is_behind(
    io: LoopThread, pair: tuple[socket.socket, socket.socket]
) -> None:
    """The kernel takes at most `PACED_BYTES` it has not sent, the stream queues as many
    again, and then the publisher waits until the peer reads; nothing is lost."""
    mine, peer = pair
    stream = OutgoingStream(mine, io, None, paced=True)
    assert (stream.paced, stream.high_water) == (True, PACED_BYTES)
    assert mine.getsockopt(socket.IPPROTO_TCP, socket.TCP_NOTSENT_LOWAT) == PACED_BYTES
    stream._drained = noted = NotedWait(stream._lock)
    frames = [twist_frame(number, 1020) for number in range(3 * PACED_BYTES // 1024)]
    handed = 0  # frames the publisher has given the stream
    done = threading.Event()

    def publish() -> None:
        nonlocal handed
        for item in frames:
            stream.send(item)
            handed += 1
        done.set()

    publisher = threading.Thread(target=publish)
    publisher.start()
    try:
        noted.until_waited(done)
        # It waits in the send of frame number ``handed``: the peer has read 4 KiB at most.
        written = (handed + 1) * 1024
        assert PACED_BYTES < written <= 2 * PACED_BYTES + 64 * 1024
        assert_delivered(stream, peer, frames)
    finally:
        stream.close()
        publisher.join(10)
    assert done.is_set()


@pytest.mark.parametrize("parts", [False, True], ids=["whole", "in parts"])
def test_a_large_frame_ends_the_pacing(
    io: LoopThread, pair: tuple[socket.socket, socket.socket], parts: bool
) -> None:
    """Large messages move faster with the kernel's buffers full: a paced publisher of them
    waits only as any other does."""
    mine, peer = pair
    stream = OutgoingStream(mine, io, None, paced=True)
    small, large = twist_frame(0), twist_frame(1, HOLD_SIZE)
    stream.send(small)
    assert stream.paced
    stream.send((large[:8], large[8:]) if parts else large)
    assert (stream.paced, stream.high_water) == (False, HIGH_WATER)
    assert mine.getsockopt(socket.IPPROTO_TCP, socket.TCP_NOTSENT_LOWAT) == 0
    assert_delivered(stream, peer, [small, large])
    stream.close()


@pytest.mark.parametrize(
    ("queue_size", "paced"),
    [(None, True), (0, False), (100, False)],
    ids=["queue None", "unbounded", "queue 100"],
)
def test_a_publication_paces_over_tcp_only_a_publisher_that_waits(
    make_node: Callable[..., Node],
    monkeypatch: pytest.MonkeyPatch,
    queue_size: int | None,
    paced: bool,
) -> None:
    """``queue_size=None`` waits for a subscriber that is behind, as rospy's synchronous
    publisher does; 0 queues without end and a size drops, as in ROS 1: neither waits."""
    _, link = linked_over_tcp(make_node, monkeypatch, lambda msg: None, queue_size)
    lowat = link.stream.sock.getsockopt(socket.IPPROTO_TCP, socket.TCP_NOTSENT_LOWAT)
    assert (link.stream.paced, lowat, link.stream.high_water) == (
        (True, PACED_BYTES, PACED_BYTES) if paced else (False, 0, HIGH_WATER)
    )
