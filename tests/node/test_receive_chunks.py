"""A subscriber reads frames whole however the publisher's bytes are cut up on the way.

A read that holds exactly one whole frame is handed over at once (with one callback, its
reader thread runs it straight from the read); anything else goes through the stream's frame
reader. The publisher here is a bare TCPROS socket, so the test decides
where each read ends: it waits, through ``getBusStats``, until the subscriber has read every
byte sent before sending the next piece.
"""

from __future__ import annotations

import contextlib
import re
import socket
import threading
from collections.abc import Callable, Iterator
from typing import Any
from xmlrpc.server import SimpleXMLRPCServer

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.message import serialize_frame
from rosx.node import Node, incoming, rosout, subscription
from rosx.transport.client import call
from rosx.wire.framing import FrameReader
from rosx.wire.header import decode_header, encode_header
from tests.support.procs import wait_for

String = get_message_class("std_msgs/String")


@contextlib.contextmanager
def bare_publisher(
    topic: str, answer: threading.Event | None = None, *, refuse: bool = False
) -> Iterator[tuple[str, socket.socket]]:
    """A Slave API that answers ``requestTopic`` with a TCPROS socket of the test's own, or
    (``refuse``) as a node that no longer publishes the topic; once ``answer`` is set, if
    given."""
    listener = socket.create_server(("127.0.0.1", 0))
    port = listener.getsockname()[1]
    server = SimpleXMLRPCServer(("127.0.0.1", 0), logRequests=False)

    def request_topic(*_: object) -> list[object]:
        if answer is not None:
            answer.wait(30)
        if refuse:
            return [-1, f"Not a publisher of [{topic}]", []]
        return [1, "", ["TCPROS", "127.0.0.1", port]]

    server.register_function(request_topic, "requestTopic")
    server.register_function(lambda *_: [1, "", [[topic, "std_msgs/String"]]], "getPublications")
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/", listener
    finally:
        server.shutdown()
        server.server_close()
        thread.join()
        listener.close()


def accept_subscriber(
    listener: socket.socket, topic: str, behind: bytes = b"", *, latching: bool = False
) -> socket.socket:
    """Take the subscriber's connection and answer its header as a publisher (``behind`` it,
    in the same ``send``, whatever is given)."""
    listener.settimeout(30)
    conn, _ = listener.accept()
    conn.settimeout(30)
    conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    reader = FrameReader()
    while (block := reader.next_frame()) is None:
        reader.feed(conn.recv(65536))
    assert decode_header(block)["topic"] == topic
    reply = {
        "callerid": "/bare_pub",
        "topic": topic,
        "type": "std_msgs/String",
        "md5sum": String._md5sum,
        "message_definition": String._full_text,
    }
    if latching:
        reply["latching"] = "1"
    conn.sendall(encode_header(reply) + behind)
    return conn


@contextlib.contextmanager
def fed_by_a_bare_publisher(
    node: Node,
    master: str,
    topic: str,
    data_class: Any,
    callback: Callable[[Any], object],
    behind: bytes = b"",
    *,
    latching: bool = False,
) -> Iterator[tuple[Any, socket.socket]]:
    """``node`` subscribed to ``topic``, whose one publisher is a bare socket of the test's:
    the subscriber and that socket (``behind``: sent with the header)."""
    with bare_publisher(topic) as (uri, listener):
        call(master, "registerPublisher", "/bare_pub", topic, "std_msgs/String", uri)
        sub = node.subscribe(topic, data_class, callback)
        with accept_subscriber(listener, topic, behind, latching=latching) as conn:
            yield sub, conn


def bytes_read(node: Node, topic: str) -> Callable[[], int]:
    """What the node's subscriber has read from its one connection to ``topic``."""

    def count() -> int:
        _, _, (_, subscriptions, _) = call(node.uri, "getBusStats", "/test")
        for name, connections in subscriptions:
            if name == topic and connections:
                return int(connections[0][1])
        return 0

    return count


def test_frames_cut_anywhere_arrive_whole_and_in_order(
    make_node: Callable[..., Node], master: str
) -> None:
    topic = "/chunks"
    node = make_node("chunk_listener")
    got: list[str] = []
    with fed_by_a_bare_publisher(node, master, topic, String, lambda msg: got.append(msg.data)) as (
        sub,
        conn,
    ):
        frames = {text: serialize_frame(String(data=text)) for text in "abcdefgh"}
        read = bytes_read(node, topic)
        wait_for(lambda: sub.get_num_connections() == 1)
        a, b, c, d, e, f, g, h = frames.values()
        pieces = [
            a,  # one whole frame
            b[:2],  # part of a length
            b[2:] + c,  # the rest, then a whole frame
            d + e[:7],  # a whole frame and part of the next one's payload
            e[7:],  # its end
            f,  # a whole frame again
            g + h,  # two in one read
        ]
        sent = 0
        for piece in pieces:
            conn.sendall(piece)
            sent += len(piece)
            wait_for(lambda: read() == sent)  # noqa: B023 - awaited before `sent` changes
        wait_for(lambda: len(got) == len(frames))
    assert got == list("abcdefgh")


def test_an_empty_frame_is_a_message(make_node: Callable[..., Node], master: str) -> None:
    """A frame of no bytes (``std_msgs/Empty``'s) read alone is one message."""
    topic = "/empties"
    node = make_node("empty_listener")
    got: list[Any] = []
    with fed_by_a_bare_publisher(node, master, topic, None, got.append) as (sub, conn):
        read = bytes_read(node, topic)
        wait_for(lambda: sub.get_num_connections() == 1)
        conn.sendall(b"\0\0\0\0")
        wait_for(lambda: read() == 4)
        conn.sendall(serialize_frame(String(data="x")))
        wait_for(lambda: len(got) == 2)
    assert [bytes(m._buff) for m in got] == [b"", b"\x01\0\0\0x"]


def test_a_message_right_behind_the_header_is_read_and_counted(
    make_node: Callable[..., Node], master: str
) -> None:
    """Bytes that come in the handshake's read count in ``getBusStats`` as later ones do."""
    topic = "/eager"
    node = make_node("eager_listener")
    got: list[str] = []
    frame = serialize_frame(String(data="first"))
    with fed_by_a_bare_publisher(
        node, master, topic, String, lambda msg: got.append(msg.data), behind=frame
    ):
        wait_for(lambda: got == ["first"])
        assert bytes_read(node, topic)() == len(frame)


@pytest.mark.parametrize("ending", ["open", "out of sync", "out of sync, then more"])
def test_a_backlog_taken_in_many_reads_arrives_whole_and_in_order(
    make_node: Callable[..., Node], master: str, monkeypatch: pytest.MonkeyPatch, ending: str
) -> None:
    """What waits in the socket while a callback runs is read in one go, read after read
    (`rosx.node.incoming`, its reads made small here so the backlog takes many), its frames
    cut anywhere by the reads: each arrives whole, in order, counted once. A length out of
    bounds at its end drops the connection once the frames before it are delivered, whatever
    follows it, at once and with one line, not when the publisher next sends."""
    monkeypatch.setattr(incoming, "RECV_SIZE", 1024)
    topic = "/backlog"
    lines: list[tuple[int, str]] = []
    node = make_node("backlog_listener", console=lambda level, line: lines.append((level, line)))
    got: list[str] = []
    release = threading.Event()

    def callback(msg: Any) -> None:
        got.append(msg.data)
        if msg.data == "first":
            release.wait(30)  # the reader is busy: the backlog waits in the socket

    with fed_by_a_bare_publisher(node, master, topic, String, callback) as (sub, conn):
        read = bytes_read(node, topic)
        wait_for(lambda: sub.get_num_connections() == 1)
        first = serialize_frame(String(data="first"))
        conn.sendall(first)
        wait_for(lambda: got == ["first"])
        # Frames shorter and longer than a read: some whole in one, some over two or three.
        texts = [f"{n:03d}" + "x" * (2500 if n % 16 == 5 else n * 37 % 300) for n in range(80)]
        backlog = b"".join(serialize_frame(String(data=text)) for text in texts)
        # Out of sync: a length no frame has, then a few bytes or more than two reads' worth.
        bad = b"\xff\xff\xff\xff"
        behind = {
            "open": b"",
            "out of sync": bad + b" junk",
            "out of sync, then more": bad + b"junk" * 1024,
        }
        conn.sendall(backlog + behind[ending])
        release.set()
        wait_for(lambda: len(got) == 1 + len(texts), what="the backlog")
        assert got == ["first", *texts]
        if ending == "open":
            wait_for(lambda: read() == len(first) + len(backlog))
        else:
            with contextlib.suppress(ConnectionResetError):  # closed with the junk unread
                assert conn.recv(1) == b""  # the subscriber closed its end
            errors = [line for level, line in lines if level == rosout.ERROR]
            assert len(errors) == 1
            assert re.fullmatch(
                r"\[ERROR\] \[\d+\.\d+\]: \[/backlog\] dropping connection to "
                r"\[http://127\.0\.0\.1:\d+/\]: frame of 4294967295 bytes exceeds the limit of "
                r"1000000000 bytes; the peer is out of sync or sends more than this side accepts",
                errors[0],
            )


def send_each(conn: socket.socket, read: Callable[[], int], texts: str) -> None:
    """Send one whole frame per text, each once the subscriber has read all before it."""
    sent = read()
    for text in texts:
        frame = serialize_frame(String(data=text))
        conn.sendall(frame)
        sent += len(frame)
        wait_for(lambda: read() == sent)  # noqa: B023 - awaited before `sent` changes


def test_a_callback_that_raises_is_reported_and_reading_goes_on(
    make_node: Callable[..., Node], master: str
) -> None:
    topic = "/raising"
    lines: list[tuple[int, str]] = []
    node = make_node("raising_listener", console=lambda level, line: lines.append((level, line)))
    got: list[str] = []

    def callback(msg: Any) -> None:
        got.append(msg.data)
        if msg.data == "b":
            raise ValueError("no b")

    with fed_by_a_bare_publisher(node, master, topic, String, callback) as (sub, conn):
        wait_for(lambda: sub.get_num_connections() == 1)
        send_each(conn, bytes_read(node, topic), "abc")
        wait_for(lambda: len(got) == 3)
    assert got == ["a", "b", "c"]
    errors = [line for level, line in lines if level == rosout.ERROR]
    assert len(errors) == 1
    assert "bad callback: <function" in errors[0] and "ValueError: no b" in errors[0]


def test_callbacks_added_and_removed_while_a_topic_is_read(
    make_node: Callable[..., Node], master: str
) -> None:
    """A callback added between two messages gets the second; one removed gets no more."""
    topic = "/joining"
    node = make_node("joining_listener")
    first: list[str] = []
    second: list[str] = []
    with fed_by_a_bare_publisher(node, master, topic, String, lambda m: first.append(m.data)) as (
        sub,
        conn,
    ):
        read = bytes_read(node, topic)
        wait_for(lambda: sub.get_num_connections() == 1)
        send_each(conn, read, "a")
        wait_for(lambda: first == ["a"])
        other = node.subscribe(topic, String, lambda m: second.append(m.data))
        send_each(conn, read, "b")
        wait_for(lambda: first == ["a", "b"] and second == ["b"])
        other.unregister()
        send_each(conn, read, "c")
        wait_for(lambda: first == ["a", "b", "c"])
    assert second == ["b"]


def test_a_late_callback_gets_the_last_message_read_from_a_latching_publisher(
    make_node: Callable[..., Node], master: str
) -> None:
    topic = "/latching"
    node = make_node("latch_listener")
    first: list[str] = []
    late: list[str] = []
    with fed_by_a_bare_publisher(
        node, master, topic, String, lambda m: first.append(m.data), latching=True
    ) as (sub, conn):
        wait_for(lambda: sub.get_num_connections() == 1)
        send_each(conn, bytes_read(node, topic), "ab")
        wait_for(lambda: first == ["a", "b"])
        node.subscribe(topic, String, lambda m: late.append(m.data))
        wait_for(lambda: late == ["b"])
    assert first == ["a", "b"]


@pytest.mark.parametrize("callbacks", [1, 2])
def test_what_a_publisher_sent_before_it_left_is_still_delivered(
    make_node: Callable[..., Node], master: str, callbacks: int
) -> None:
    """A ``publisherUpdate`` without the publisher (it unregistered) does not cut what it sent
    before (``rostopic pub -1`` leaves right after sending), however late it is read."""
    topic = "/leaving"
    node = make_node("leaving_listener")
    got: list[str] = []
    release = threading.Event()

    def callback(msg: Any) -> None:
        got.append(msg.data)
        if msg.data == "a":
            release.wait(30)  # the reader is busy: "b" waits in the socket

    with fed_by_a_bare_publisher(node, master, topic, String, callback) as (sub, conn):
        for _ in range(1, callbacks):
            node.subscribe(topic, String, lambda m: None)
        wait_for(lambda: sub.get_num_connections() == 1)
        conn.sendall(serialize_frame(String(data="a")))
        wait_for(lambda: got == ["a"])
        conn.sendall(serialize_frame(String(data="b")))
        assert call(node.uri, "publisherUpdate", "/master", topic, [])[0] == 1
        wait_for(lambda: sub.get_num_connections() == 0)
        conn.close()  # the publisher is gone
        release.set()
        wait_for(lambda: got == ["a", "b"])


def test_a_retired_connection_its_publisher_keeps_open_is_closed_in_time(
    make_node: Callable[..., Node], master: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(subscription, "RETIRE_GRACE", 0.2)
    topic = "/lingering"
    node = make_node("lingering_listener")
    got: list[str] = []
    with fed_by_a_bare_publisher(node, master, topic, String, lambda m: got.append(m.data)) as (
        sub,
        conn,
    ):
        wait_for(lambda: sub.get_num_connections() == 1)
        conn.sendall(serialize_frame(String(data="x")))
        wait_for(lambda: got == ["x"])
        assert call(node.uri, "publisherUpdate", "/master", topic, [])[0] == 1
        conn.settimeout(30)
        assert conn.recv(1) == b""  # the subscriber closed its end


def test_a_publisher_that_left_while_it_was_being_connected_still_delivers(
    make_node: Callable[..., Node], master: str
) -> None:
    """The publisher's ``publisherUpdate`` came, then one without it, before the connection
    was made: the handshake goes on, and what the publisher sent is delivered."""
    topic = "/hasty"
    node = make_node("hasty_listener")
    got: list[str] = []
    answer = threading.Event()
    with bare_publisher(topic, answer) as (uri, listener):
        call(master, "registerPublisher", "/bare_pub", topic, "std_msgs/String", uri)
        sub = node.subscribe(topic, String, lambda m: got.append(m.data))
        wait_for(lambda: sub.subscription.streams, what="the connection under way")
        assert call(node.uri, "publisherUpdate", "/master", topic, [])[0] == 1
        answer.set()
        frame = serialize_frame(String(data="once"))
        with accept_subscriber(listener, topic, frame) as conn:
            wait_for(lambda: got == ["once"])
            conn.close()


def test_a_publisher_that_left_and_refuses_the_topic_is_let_go_quietly(
    make_node: Callable[..., Node], master: str
) -> None:
    topic = "/gone"
    lines: list[tuple[int, str]] = []
    node = make_node("quiet_listener", console=lambda level, line: lines.append((level, line)))
    answer = threading.Event()
    with bare_publisher(topic, answer, refuse=True) as (uri, _):
        call(master, "registerPublisher", "/bare_pub", topic, "std_msgs/String", uri)
        sub = node.subscribe(topic, String, lambda m: None)
        subscription = sub.subscription
        wait_for(lambda: subscription.streams, what="the connection under way")
        (stream,) = subscription.streams.values()
        assert call(node.uri, "publisherUpdate", "/master", topic, [])[0] == 1
        answer.set()
        wait_for(lambda: stream.closed, what="the stream's end")
    assert sub.get_num_connections() == 0
    assert [line for level, line in lines if level >= rosout.WARN] == []
