"""The WebSocket shell: bad input over a real connection (a status, the server still serving this
client and the others), 1009 for an oversized frame, the Origin check, the token, and a slow
client that never holds up the others."""

from __future__ import annotations

import json
import time
from collections.abc import Iterator
from typing import Any

import pytest
from websockets.exceptions import ConnectionClosed, InvalidStatus
from websockets.sync.client import ClientConnection, connect
from websockets.typing import Origin

from rosx.bridge.app import Bridge
from tests.support.bridge import Running, start_bridge


def receive_json(ws: ClientConnection, timeout: float = 10.0) -> dict[str, Any]:
    data = json.loads(ws.recv(timeout=timeout))
    assert isinstance(data, dict)
    return data


def next_op(ws: ClientConnection, op: str, timeout: float = 10.0) -> dict[str, Any]:
    deadline = time.monotonic() + timeout
    while True:
        data = receive_json(ws, max(0.01, deadline - time.monotonic()))
        if data["op"] == op:
            return data


def pose_arrives(ws: ClientConnection) -> None:
    ws.send(json.dumps({"op": "subscribe", "topic": "/turtle1/pose", "id": "pose"}))
    assert next_op(ws, "publish")["topic"] == "/turtle1/pose"
    ws.send(json.dumps({"op": "unsubscribe", "topic": "/turtle1/pose", "id": "pose"}))


@pytest.fixture
def ws(running: Running) -> Iterator[ClientConnection]:
    with connect(running.url, max_size=None) as conn:
        yield conn


BAD = [
    ('{"op": "publish", "topic": "/a"', "Invalid JSON (Expecting ',' delimiter"),
    ("[]", "Expected a JSON object with an 'op' field but received an array"),
    ('{"id": 1}', "Received a message without an op."),
    ('{"op": "dance"}', "Unknown operation: dance."),
    (
        '{"op": "subscribe", "topic": "/x", "type": "no/Type"}',
        "subscribe: Unknown message type no/Type",
    ),
    ('{"op": "advertise", "topic": "/cmd", "type": "geometry_msgs/Twist"}', None),
    (
        '{"op": "publish", "topic": "/cmd", "msg": {"linear": {"x": "a"}}}',
        "publish: geometry_msgs/Twist message requires a float64 for field linear.x, but got a string",
    ),
    (
        '{"op": "call_service", "service": "/nobody_serves_this"}',
        "call_service /nobody_serves_this: service [/nobody_serves_this] unavailable",
    ),
]


def test_bad_input_gets_a_status_and_the_connection_goes_on(
    ws: ClientConnection, running: Running
) -> None:
    with connect(running.url) as other:
        for frame, text in BAD:
            ws.send(frame)
            if text is None:
                continue
            status = next_op(ws, "status")
            assert (status["level"], status["msg"][: len(text)]) == ("error", text)
        ws.send('{"op": "set_level", "level": "none"}')  # told nothing, logged all the same
        ws.send('{"op": "dance", "id": "d1"}')
        pose_arrives(ws)
        pose_arrives(other)
    # the bridge's terminal says what it refused, as rosbridge_suite's log does
    logged = [text for _, text in BAD if text] + ["[id: d1] Unknown operation: dance."]

    def all_logged() -> bool:
        client = [line for line in running.lines if line.startswith("[Client 127.0.0.1] ")]
        return all(any(want in line for line in client) for want in logged)

    deadline = time.monotonic() + 10
    while not all_logged():
        assert time.monotonic() < deadline, running.lines
        time.sleep(0.01)


def test_an_oversized_frame_closes_with_1009_after_a_status(master: str) -> None:
    bridge, _ = start_bridge(master, rosapi=False, max_message=1000)
    try:
        url = f"ws://127.0.0.1:{bridge.port}"
        with connect(url) as ws, connect(url) as other:
            ws.send("x" * 5000)
            status = receive_json(ws)
            assert status["op"] == "status"
            assert status["msg"].endswith("the limit is 1000 bytes (--max-message-size)")
            with pytest.raises(ConnectionClosed) as closed:
                ws.recv(timeout=10)
            assert closed.value.rcvd is not None
            assert closed.value.rcvd.code == 1009
            other.send(json.dumps({"op": "set_level", "level": "info"}))
            assert next_op(other, "status")["msg"] == "Status level set to info"
    finally:
        bridge.shutdown("test over")


def test_a_foreign_page_is_refused_and_a_local_one_served(running: Running) -> None:
    with pytest.raises(InvalidStatus) as refused:
        connect(running.url, origin=Origin("https://evil.example"))
    assert refused.value.response.status_code == 403
    assert b"Origin https://evil.example is not allowed" in (refused.value.response.body or b"")
    with connect(running.url, origin=Origin("http://localhost:8080")) as ws:
        pose_arrives(ws)
    assert any(
        "Refused a connection from a page of https://evil.example" in line for line in running.lines
    )


def test_a_refused_page_is_told_in_the_log_how_to_let_it_in(running: Running) -> None:
    # Browsers give a page opened from a file the origin "null", as sandboxed frames of any site.
    with pytest.raises(InvalidStatus):
        connect(running.url, origin=Origin("null"))
    line = (
        "Refused a connection from a page of null: not an allowed origin (--allow-origin null, "
        "or allow_origin:=null with roslaunch, lets its pages connect)"
    )
    deadline = time.monotonic() + 10
    while line not in running.lines:
        assert time.monotonic() < deadline, running.lines
        time.sleep(0.01)
    # Chromium with --allow-file-access-from-files says "file://": a page of this machine.
    with connect(running.url, origin=Origin("file://")) as ws:
        pose_arrives(ws)


def test_a_message_published_as_the_topic_is_advertised_reaches_subscribers(
    running: Running,
) -> None:
    # The roslibjs tutorial's page publishes once, at load: the subscribers connect to the new
    # publisher after the message is sent, and get it all the same (rosbridge_suite keeps a
    # publisher's first second for them).
    from rosx.msg.codec.classes import get_message_class
    from rosx.node import Node

    twist_class = get_message_class("geometry_msgs/Twist")
    listener = Node("cmd_vel_listener", master_uri=running.master, environ=running.environ)
    got: list[float] = []
    listener.start().subscribe("/tutorial_cmd_vel", twist_class, lambda m: got.append(m.linear.x))
    try:
        with connect(running.url) as ws:
            advertise = {
                "op": "advertise",
                "topic": "/tutorial_cmd_vel",
                "type": "geometry_msgs/Twist",
            }
            ws.send(json.dumps(advertise))
            ws.send(
                json.dumps(
                    {"op": "publish", "topic": "/tutorial_cmd_vel", "msg": {"linear": {"x": 0.1}}}
                )
            )
            deadline = time.monotonic() + 10
            while not got and time.monotonic() < deadline:
                time.sleep(0.01)
    finally:
        listener.shutdown("test over")
    assert got == [0.1]


def test_a_token_guards_the_bridge(master: str) -> None:
    bridge, _ = start_bridge(master, rosapi=False, token="let-me-in")
    try:
        url = f"ws://127.0.0.1:{bridge.port}"
        with connect(url) as ws:
            ws.send(json.dumps({"op": "subscribe", "topic": "/rosout"}))
            assert (
                next_op(ws, "status")["msg"]
                == "subscribe: not authenticated: send an 'auth' op first"
            )
            ws.send(json.dumps({"op": "auth", "mac": "let-me-in"}))
            ws.send(json.dumps({"op": "set_level", "level": "info"}))
            assert next_op(ws, "status")["msg"] == "Status level set to info"
        with connect(url) as ws:
            ws.send(json.dumps({"op": "auth", "mac": "wrong"}))
            with pytest.raises(ConnectionClosed) as closed:
                while True:
                    ws.recv(timeout=10)
            assert closed.value.rcvd is not None
            assert closed.value.rcvd.code == 1008
        with connect(url + "/?token=let-me-in") as ws:
            ws.send(json.dumps({"op": "set_level", "level": "info"}))
            assert next_op(ws, "status")["msg"] == "Status level set to info"
    finally:
        bridge.shutdown("test over")


def test_a_slow_client_loses_its_oldest_messages_not_the_others_time(master: str) -> None:
    bridge, lines = start_bridge(master, rosapi=False)
    try:
        _slow_and_fast(bridge, lines)
    finally:
        bridge.shutdown("test over")


def _slow_and_fast(bridge: Bridge, lines: list[str]) -> None:
    from rosx.msg.codec.classes import get_message_class
    from rosx.node import Node

    url = f"ws://127.0.0.1:{bridge.port}"
    string_class = get_message_class("std_msgs/String")
    subscribe = {"op": "subscribe", "topic": "/bulk", "type": "std_msgs/String", "id": "s"}
    count, pad = 3000, "x" * 10_000
    with connect(url) as slow, connect(url, max_size=None) as fast:
        slow.send(json.dumps({**subscribe, "queue_length": 5}))
        fast.send(json.dumps({**subscribe, "queue_length": count}))
        publisher = Node(
            "bulk", master_uri=bridge.options.master_uri, environ=bridge.options.environ
        ).start()
        try:
            pub = publisher.advertise("/bulk", string_class, queue_size=None)
            deadline = time.monotonic() + 10
            while pub.get_num_connections() < 1 and time.monotonic() < deadline:
                time.sleep(0.01)
            # The slow client reads nothing while 30 MB go out: its socket fills, then its queue.
            for n in range(count):
                pub.publish(string_class(f"{n} {pad}"))
            seen = [int(next_op(fast, "publish")["msg"]["data"].split()[0]) for _ in range(count)]
            assert seen == list(range(count))
            server = bridge.server
            assert server is not None
            (slow_conn,) = [c for c in server.connections if c.remote_address == slow.local_address]
            assert slow_conn.dropped_total() > 0
            got: list[int] = []
            while not got or got[-1] != count - 1:
                got.append(int(next_op(slow, "publish")["msg"]["data"].split()[0]))
            assert len(got) + slow_conn.dropped_total() == count
            assert got == sorted(got)
        finally:
            publisher.shutdown("test over")
    dropped = slow_conn.dropped_total()
    line = (
        f"Client was sent {dropped} messages fewer on /bulk: it read slower than they came "
        "(its oldest were dropped)"
    )
    deadline = time.monotonic() + 10
    while line not in lines and time.monotonic() < deadline:
        time.sleep(0.01)
    assert line in lines


def test_two_clients_cannot_publish_one_topic_with_two_types(running: Running) -> None:
    with connect(running.url) as first, connect(running.url) as second:
        first.send(json.dumps({"op": "set_level", "level": "info"}))
        first.send(json.dumps({"op": "advertise", "topic": "/typed", "type": "std_msgs/String"}))
        assert next_op(first, "status")["msg"] == "Status level set to info"
        assert next_op(first, "status")["msg"] == "Advertised /typed"
        second.send(json.dumps({"op": "advertise", "topic": "/typed", "type": "std_msgs/Int32"}))
        status = next_op(second, "status")
        assert status["msg"] == "advertise: /typed is already advertised with type std_msgs/String"
        second.send(json.dumps({"op": "publish", "topic": "/typed", "msg": {"data": 1}}))
        status = next_op(second, "status")
        assert status["msg"] == (
            "publish: std_msgs/String message requires a string for field data, but got a number"
        )
