"""A rosx publisher and a roscpp subscriber (over TCPROS): large images, which rosx sends from
the message itself in parts (`rosx.msg.codec.parts`), reach roscpp as the same bytes, in order,
latched ones too; a slow roscpp subscriber loses only the oldest, with the publisher's queue,
and none from an unbounded one, however far behind it fell. A publisher that waits
(``queue_size=None``) of small messages waits for a stopped roscpp subscriber once about a
megabyte is on its way, then sends it every message; one that dies sets it free.

The roscpp node is `roscpp/image_listener.cpp`, compiled here against Debian's libroscpp-dev
(`bench.roscpp_program.build`, cached); skipped where a compiler, roscpp or the message headers
are missing. It runs on the tests' rosx master and prints a line per message.
"""

from __future__ import annotations

import os
import queue
import signal
import subprocess
import threading
import zlib
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from bench.roscpp_program import build
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from rosx.node.outgoing import OutgoingStream
from tests.support.frames import NotedWait
from tests.support.procs import wait_for

Image = get_message_class("sensor_msgs/Image")
SOURCE = Path(__file__).resolve().parent / "roscpp" / "image_listener.cpp"


@pytest.fixture(scope="module")
def listener_program() -> Path:
    built = build(SOURCE)
    if isinstance(built, str):
        pytest.skip(f"roscpp: {built}")
    return built


class Listener:
    """The roscpp subscriber's process and the lines it printed."""

    def __init__(self, proc: subprocess.Popen[str]) -> None:
        self.proc = proc
        self.lines: queue.Queue[str] = queue.Queue()
        self.seen: list[tuple[str, int, int]] = []
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            self.lines.put(line.strip())

    def next_line(self) -> str:
        return self.lines.get(timeout=30)

    def until(self, frame_id: str) -> list[tuple[str, int, int]]:
        """What it received, up to and including the message ``frame_id``."""
        while not self.seen or self.seen[-1][0] != frame_id:
            name, size, crc = self.next_line().split()
            self.seen.append((name, int(size), int(crc, 16)))
        return self.seen


@pytest.fixture
def start_listener(
    master: str, listener_program: Path, tmp_path: Path
) -> Iterator[Callable[[str, int, int], Listener]]:
    procs: list[subprocess.Popen[str]] = []

    def start(topic: str, queue_size: int, delay_ms: int) -> Listener:
        env = dict(os.environ, ROS_MASTER_URI=master, ROS_IP="127.0.0.1", ROS_HOME=str(tmp_path))
        proc = subprocess.Popen(
            [str(listener_program), topic, str(queue_size), str(delay_ms)],
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            text=True,
            env=env,
        )
        procs.append(proc)
        listener = Listener(proc)
        assert listener.next_line() == "ready"
        return listener

    yield start
    for proc in procs:
        proc.kill()
        proc.wait()


def expected(name: str, data: bytes | bytearray) -> tuple[str, int, int]:
    return (name, len(data), zlib.crc32(data))


def test_every_image_reaches_roscpp_as_published(
    make_node: Callable[..., Node], start_listener: Callable[[str, int, int], Listener]
) -> None:
    node = make_node("camera")
    pub = node.advertise("/camera", Image, queue_size=None, latch=True)
    msg = Image(height=1, encoding="mono8")
    sent: list[tuple[str, int, int]] = []

    def publish(name: str, data: bytes | bytearray) -> None:
        msg.header.frame_id = name
        msg.width = msg.step = len(data)
        msg.data = data
        pub.publish(msg)
        sent.append(expected(name, data))

    publish("latched", bytes(range(256)) * 8192)  # before roscpp subscribes: the latch
    listener = start_listener("/camera", 100, 0)
    wait_for(lambda: pub.get_num_connections() == 1)
    assert listener.until("latched") == sent
    sizes = [3 << 20, 10, 40_000, 1 << 20, 0, 32 * 1024, 32 * 1024 - 1, 2 << 20]
    for number, size in enumerate(sizes):
        data = bytes([number]) * size
        publish(str(number), data if number % 3 else bytearray(data))
        msg.data = b"changed after publish"  # what went out stays as it was
    assert listener.until(str(len(sizes) - 1)) == sent


def test_a_slow_roscpp_subscriber_loses_only_the_oldest(
    make_node: Callable[..., Node], start_listener: Callable[[str, int, int], Listener]
) -> None:
    node = make_node("fast_camera")
    pub = node.advertise("/fast", Image, queue_size=1)
    listener = start_listener("/fast", 1, 50)
    wait_for(lambda: pub.get_num_connections() == 1)
    images: dict[str, Any] = {}
    for number in range(30):
        data = bytes([number]) * (1 << 20)
        image = Image(width=1 << 20, encoding="mono8", data=data)
        image.header.frame_id = str(number)
        images[str(number)] = expected(str(number), data)
        pub.publish(image)
    got = listener.until("29")
    numbers = [int(name) for name, _, _ in got]
    assert numbers == sorted(set(numbers))  # in order, none twice
    assert len(numbers) < 30  # 30 MiB at once: the oldest were dropped on the way
    assert got == [images[name] for name, _, _ in got]  # the rest arrived whole


def test_a_roscpp_subscriber_far_behind_an_unbounded_queue_gets_every_message_in_order(
    make_node: Callable[..., Node], start_listener: Callable[[str, int, int], Listener]
) -> None:
    node = make_node("flood_camera")
    pub = node.advertise("/flood", Image, queue_size=0)  # unbounded: nothing dropped
    listener = start_listener("/flood", 0, 0)
    wait_for(lambda: pub.get_num_connections() == 1)
    image = Image(width=1000, height=1, step=1000, encoding="mono8")
    sent: list[tuple[str, int, int]] = []

    def publish(first: int, count: int) -> None:
        for number in range(first, first + count):
            image.header.frame_id = str(number)
            image.data = bytes([number % 251]) * 1000
            pub.publish(image)
            sent.append(expected(str(number), image.data))

    listener.proc.send_signal(signal.SIGSTOP)  # it reads nothing: 10 MB wait, most in rosx
    try:
        publish(0, 10_000)
    finally:
        listener.proc.send_signal(signal.SIGCONT)
    publish(10_000, 10_000)  # more come while it catches up
    assert listener.until("19999") == sent


class StoppedFeed:
    """A publisher thread of 1000-byte images (small: paced) with ``queue_size=None`` to a
    roscpp subscriber stopped by SIGSTOP, noting when the publisher first waits."""

    def __init__(self, node: Node, listener: Listener, count: int) -> None:
        pub = node.advertise("/paced", Image, queue_size=None)
        wait_for(lambda: pub.get_num_connections() == 1)
        (link,) = node.publications["/paced"].links
        self.stream: OutgoingStream = link.stream
        assert self.stream.paced
        self.stream._drained = self.noted = NotedWait(self.stream._lock)
        self.sent: list[tuple[str, int, int]] = []
        self.done = threading.Event()
        listener.proc.send_signal(signal.SIGSTOP)
        image = Image(width=1000, height=1, step=1000, encoding="mono8")

        def publish() -> None:
            for number in range(count):
                image.header.frame_id = str(number)
                image.data = bytes([number % 251]) * 1000
                pub.publish(image)
                self.sent.append(expected(str(number), image.data))
            self.done.set()

        self.thread = threading.Thread(target=publish, daemon=True)
        self.thread.start()


def test_a_publisher_that_waits_waits_for_a_stopped_roscpp_subscriber_then_sends_everything(
    make_node: Callable[..., Node], start_listener: Callable[[str, int, int], Listener]
) -> None:
    """rospy's synchronous publish: memory does not grow while roscpp reads nothing, and
    nothing is lost."""
    listener = start_listener("/paced", 0, 0)
    feed = StoppedFeed(make_node("paced_camera"), listener, 10_000)
    try:
        feed.noted.until_waited(feed.done)
        assert feed.stream.paced  # its frames are under HOLD_SIZE
        # At most its queue's limit waits in rosx (what the kernels hold is theirs), and
        # it waited well before the last message.
        assert feed.stream._pending_bytes <= feed.stream.high_water + 1100
        assert len(feed.sent) < 10_000
    finally:
        listener.proc.send_signal(signal.SIGCONT)
    feed.thread.join(30)
    assert feed.done.is_set()
    assert listener.until("9999") == feed.sent


def test_a_roscpp_subscriber_that_dies_sets_a_waiting_publisher_free(
    make_node: Callable[..., Node], start_listener: Callable[[str, int, int], Listener]
) -> None:
    listener = start_listener("/paced", 0, 0)
    node = make_node("paced_camera")
    feed = StoppedFeed(node, listener, 10_000)
    feed.noted.until_waited(feed.done)
    listener.proc.kill()  # stopped, then gone: its socket is reset
    feed.thread.join(30)
    assert feed.done.is_set()  # the rest went nowhere, as in ROS 1
    wait_for(lambda: not node.publications["/paced"].links, what="the link to close")
