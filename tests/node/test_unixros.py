"""UNIXROS: rosx nodes of one machine connect over Unix sockets, and fall back to TCPROS.

The nodes here are in one process with in-process links off (``rosx.node.local.ENABLED``), so
they connect through their sockets as nodes of two processes do.
"""

from __future__ import annotations

import socket
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node, local, unixros
from rosx.transport.client import call
from tests.support.procs import wait_for

Twist = get_message_class("geometry_msgs/Twist")


@pytest.fixture(autouse=True)
def _between_processes(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(local, "ENABLED", False)
    monkeypatch.setattr(unixros, "ENABLED", True)


def _request(node: Node, protocols: list[list[str]]) -> list[Any]:
    return call(node.uri, "requestTopic", "/test", "/offer", protocols)  # type: ignore[no-any-return]


def test_publisher_answers_by_the_offer(make_node: Callable[..., Node]) -> None:
    node = make_node("offered")
    node.advertise("/offer", Twist)
    address = node.unixros_address()
    assert address is not None and address.startswith("@rosx-")
    same = [unixros.PROTOCOL, unixros.machine()]
    assert _request(node, [same, ["TCPROS"]]) == [
        1,
        f"ready on {address}",
        [unixros.PROTOCOL, address],
    ]
    host, port = node.tcpros_address()
    tcpros = [1, f"ready on {host}:{port}", ["TCPROS", host, port]]
    # Another machine's offer, TCPROS first, or TCPROS alone: TCPROS.
    assert _request(node, [[unixros.PROTOCOL, "another-machine"], ["TCPROS"]]) == tcpros
    assert _request(node, [["TCPROS"], same]) == tcpros
    assert _request(node, [["TCPROS"]]) == tcpros
    assert _request(node, [[unixros.PROTOCOL, "another-machine"]]) == [
        0,
        "no supported protocol implementations",
        [],
    ]


def test_off_neither_offers_nor_accepts(
    make_node: Callable[..., Node], monkeypatch: pytest.MonkeyPatch
) -> None:
    node = make_node("plain")
    node.advertise("/offer", Twist)
    monkeypatch.setattr(unixros, "ENABLED", False)
    assert unixros.offer() is None
    host, port = node.tcpros_address()
    same = [unixros.PROTOCOL, unixros.machine()]
    assert _request(node, [same, ["TCPROS"]])[2] == ["TCPROS", host, port]


def test_messages_flow_over_unixros(make_node: Callable[..., Node]) -> None:
    talker, listener = make_node("u_talker"), make_node("u_listener")
    got: list[float] = []
    sub = listener.subscribe("/chat", Twist, lambda m: got.append(m.linear.x))
    pub = talker.advertise("/chat", Twist, queue_size=10)
    wait_for(lambda: pub.get_num_connections() and sub.get_num_connections())
    (row,) = listener.subscriptions["/chat"].bus_info()
    assert row[3] == unixros.PROTOCOL
    for i in range(50):
        pub.publish(_twist(i))
    wait_for(lambda: len(got) == 50)
    assert got == [float(i) for i in range(50)]


def _twist(x: float) -> Any:
    msg = Twist()
    msg.linear.x = x
    return msg


def test_unreachable_unix_socket_falls_back_to_tcpros(
    make_node: Callable[..., Node], monkeypatch: pytest.MonkeyPatch
) -> None:
    talker, listener = make_node("f_talker"), make_node("f_listener")
    # A socket nobody listens on, as from another network namespace.
    monkeypatch.setattr(talker, "unixros_address", unixros.new_address)
    pub = talker.advertise("/fallback", Twist, queue_size=10)
    got: list[float] = []
    sub = listener.subscribe("/fallback", Twist, lambda m: got.append(m.linear.x))
    wait_for(lambda: pub.get_num_connections() and sub.get_num_connections())
    (row,) = listener.subscriptions["/fallback"].bus_info()
    assert row[3] == "TCPROS"
    (out,) = talker.publications["/fallback"].bus_info()
    assert out[3] == "TCPROS"
    pub.publish(_twist(3.5))
    wait_for(lambda: got)
    assert got == [3.5]


def test_publisher_buffers_as_much_as_loopback_tcp(make_node: Callable[..., Node]) -> None:
    # A Unix socket counts each queued frame as a whole kernel buffer: the publisher's end is
    # given TCP's default maximum, so a subscriber a moment behind a flood loses nothing more
    # than over TCPROS. Linux doubles what is asked, up to net.core.wmem_max.
    talker, listener = make_node("b_talker"), make_node("b_listener")
    pub = talker.advertise("/buffered", Twist, queue_size=100)
    sub = listener.subscribe("/buffered", Twist, lambda m: None)
    wait_for(lambda: pub.get_num_connections() and sub.get_num_connections())
    (link,) = talker.publications["/buffered"].links
    assert link.transport == unixros.PROTOCOL
    wmem_max = int(Path("/proc/sys/net/core/wmem_max").read_text())
    granted = link.stream.sock.getsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF)
    assert granted >= 2 * min(unixros.SEND_BUFFER, wmem_max)
