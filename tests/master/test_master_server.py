"""rosx's master on real sockets, with rosx's own fake nodes: the calls it makes out
(publisherUpdate, paramUpdate, shutdown) arrive, in order, and a hung node holds up nobody."""

from __future__ import annotations

import socket
import threading
import time
import xmlrpc.client
from collections.abc import Callable, Iterator
from typing import Any
from xmlrpc.client import DateTime

import pytest

from rosx.master.server import MasterThread
from rosx.transport.client import XmlRpcClient
from rosx.transport.loop_thread import ServerThread


class FakeNode:
    """A node's Slave API, recording the master's calls."""

    def __init__(self) -> None:
        self.calls: list[tuple[Any, ...]] = []
        self.changed = threading.Condition()
        self.server = ServerThread(
            {
                "publisherUpdate": self._record("publisherUpdate"),
                "paramUpdate": self._record("paramUpdate"),
                "shutdown": self._record("shutdown"),
            }
        )

    def _record(self, method: str) -> Callable[..., list[Any]]:
        def handler(*params: Any) -> list[Any]:
            with self.changed:
                self.calls.append((method, *params))
                self.changed.notify_all()
            return [1, "", 0]

        return handler

    def wait_for(
        self, predicate: Callable[[list[tuple[Any, ...]]], bool], timeout: float = 5
    ) -> None:
        with self.changed:
            assert self.changed.wait_for(lambda: predicate(self.calls), timeout), self.calls


@pytest.fixture
def master() -> Iterator[MasterThread]:
    with MasterThread(notify_timeout=2.0) as running:
        yield running


@pytest.fixture
def node() -> Iterator[FakeNode]:
    fake = FakeNode()
    fake.server.start()
    try:
        yield fake
    finally:
        fake.server.close()


@pytest.fixture
def hung_uris() -> Iterator[list[str]]:
    """Nodes that accept connections and never answer: more than rosmaster has threads."""
    listeners = [socket.socket() for _ in range(6)]
    for listener in listeners:
        listener.bind(("127.0.0.1", 0))
        listener.listen(64)
    try:
        yield [f"http://127.0.0.1:{sock.getsockname()[1]}/" for sock in listeners]
    finally:
        for listener in listeners:
            listener.close()


def test_publisher_update_reaches_the_subscriber(master: MasterThread, node: FakeNode) -> None:
    client = XmlRpcClient()
    client.call(master.uri, "registerSubscriber", "/sub", "/t", "std_msgs/String", node.server.uri)
    for i in range(5):
        client.call(
            master.uri, "registerPublisher", f"/p{i}", "/t", "std_msgs/String", f"http://p{i}:1/"
        )
    final = [f"http://p{i}:1/" for i in range(5)]
    node.wait_for(
        lambda calls: bool(calls) and calls[-1] == ("publisherUpdate", "/master", "/t", final)
    )
    lists = [call[3] for call in node.calls]
    assert all(lists[i] == final[: len(lists[i])] for i in range(len(lists)))  # never out of order


def test_a_hung_node_does_not_stall_notifications(
    master: MasterThread, node: FakeNode, hung_uris: list[str]
) -> None:
    client = XmlRpcClient()
    for i, hung_uri in enumerate(hung_uris):
        client.call(
            master.uri, "registerSubscriber", f"/hung{i}", f"/t{i}", "std_msgs/String", hung_uri
        )
        client.call(
            master.uri, "registerPublisher", f"/pub{i}", f"/t{i}", "std_msgs/String", "http://x:1/"
        )
    client.call(
        master.uri, "registerSubscriber", "/live", "/live", "std_msgs/String", node.server.uri
    )
    started = time.monotonic()
    reply = client.call(
        master.uri, "registerPublisher", "/p", "/live", "std_msgs/String", "http://p:1/"
    )
    assert reply[0] == 1
    node.wait_for(lambda calls: ("publisherUpdate", "/master", "/live", ["http://p:1/"]) in calls)
    assert time.monotonic() - started < 1.0


def test_param_update_reaches_the_subscriber(master: MasterThread, node: FakeNode) -> None:
    client = XmlRpcClient()
    assert client.call(master.uri, "subscribeParam", "/n", node.server.uri, "gain")[0] == 1
    client.call(master.uri, "setParam", "/other", "gain", 2.5)
    node.wait_for(lambda calls: ("paramUpdate", "/master", "/gain/", 2.5) in calls)


def test_the_replaced_node_is_told_to_shut_down(master: MasterThread, node: FakeNode) -> None:
    client = XmlRpcClient()
    client.call(
        master.uri, "registerPublisher", "/talker", "/t", "std_msgs/String", node.server.uri
    )
    client.call(
        master.uri, "registerPublisher", "/talker", "/t", "std_msgs/String", "http://new:1/"
    )
    node.wait_for(
        lambda calls: (
            (
                "shutdown",
                "/master",
                "[/talker] Reason: new node registered with same name",
            )
            in calls
        )
    )
    assert client.call(master.uri, "lookupNode", "/x", "/talker") == [
        1,
        "node api",
        "http://new:1/",
    ]


def test_bad_input_is_refused_and_the_master_keeps_serving(master: MasterThread) -> None:
    port = int(master.uri.rsplit(":", 1)[1].rstrip("/"))
    junks = (
        b"\x00\xff garbage\r\n\r\n",
        b"POST / HTTP/1.1\r\nContent-Length: 3\r\n\r\n<x>",
        "POST / HTTP/1.1\r\nContent-Length: ²\r\n\r\n".encode("latin-1"),
    )
    for junk in junks:
        with socket.create_connection(("127.0.0.1", port), timeout=5) as sock:
            sock.sendall(junk)
            assert sock.recv(65536).startswith(b"HTTP/1.1 ")
    client = XmlRpcClient()
    assert client.call(master.uri, "getSystemState", "/x") == [
        1,
        "current system state",
        [[], [], []],
    ]
    assert client.call(master.uri, "setParam", "/x", "/big", 2**40 // 2**20)[0] == 1
    assert client.call(master.uri, "getParam", "/x", "/big") == [1, "Parameter [/big]", 2**20]


def test_date_times_are_stored_and_the_tree_stays_readable(master: MasterThread) -> None:
    date = "<value><dateTime.iso8601>20240102T03:04:05</dateTime.iso8601></value>"
    body = (
        "<methodCall><methodName>setParam</methodName><params><param><value>/t</value></param>"
        f"<param><value>/when</value></param><param>{date}</param></params></methodCall>"
    )
    host, port = master.uri.split("//")[1].rstrip("/").rsplit(":", 1)
    with socket.create_connection((host, int(port)), timeout=5) as sock:
        head = f"POST / HTTP/1.1\r\nHost: x\r\nContent-Length: {len(body)}\r\n\r\n"
        sock.sendall(head.encode() + body.encode())
        assert b"parameter /when set" in sock.recv(65536)
    proxy = xmlrpc.client.ServerProxy(master.uri)
    assert proxy.getParam("/x", "/when") == [1, "Parameter [/when]", DateTime("20240102T03:04:05")]
    whole: Any = proxy.getParam("/x", "/")
    assert (whole[0], whole[2]["when"]) == (1, DateTime("20240102T03:04:05"))
