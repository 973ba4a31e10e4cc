"""The WebSocket shell under the rosbridge server, over real sockets: pings, messages in
fragments, text that is not UTF-8, requests that are not WebSocket handshakes, and the end of a
connection from either side."""

from __future__ import annotations

import json
import socket
import time

import pytest
from websockets.exceptions import ConnectionClosed
from websockets.frames import Frame, Opcode
from websockets.sync.client import connect

from tests.support.bridge import Running, start_bridge

HANDSHAKE = (
    b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
    b"Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n"
)


def read_until(sock: socket.socket, end: bytes, timeout: float = 10.0) -> bytes:
    """What ``sock`` receives up to ``end`` or the end of the stream."""
    sock.settimeout(timeout)
    data = b""
    while end not in data:
        chunk = sock.recv(4096)
        if not chunk:
            break
        data += chunk
    return data


def status_text(ws: object, timeout: float = 10.0) -> str:
    """The ``msg`` of the next status the client ``ws`` gets."""
    deadline = time.monotonic() + timeout
    while True:
        data = json.loads(ws.recv(timeout=max(0.01, deadline - time.monotonic())))  # type: ignore[attr-defined]
        if data["op"] == "status":
            return str(data["msg"])


def test_a_ping_is_answered(running: Running) -> None:
    with connect(running.url) as ws:
        assert ws.ping().wait(10)


def test_a_message_in_fragments_is_one_request(running: Running) -> None:
    with connect(running.url) as ws:
        ws.send(iter(['{"op": "set_level", ', '"level": "info"}']))
        assert status_text(ws) == "Status level set to info"


def test_text_that_is_not_utf8_closes_with_1007(running: Running) -> None:
    with socket.create_connection(("127.0.0.1", running.port)) as sock:
        sock.sendall(HANDSHAKE)
        assert read_until(sock, b"\r\n\r\n").startswith(b"HTTP/1.1 101")
        sock.sendall(Frame(Opcode.TEXT, b"\xff\xfe").serialize(mask=True, extensions=[]))
        closing = read_until(sock, b"\xff" * 64)  # to the end of the stream
    assert closing[0] == 0x88  # a close frame
    assert int.from_bytes(closing[2:4], "big") == 1007
    with connect(running.url) as ws:  # the server still serves
        ws.send(json.dumps({"op": "set_level", "level": "info"}))
        assert status_text(ws) == "Status level set to info"


def test_a_request_that_is_not_a_handshake_gets_an_http_error(running: Running) -> None:
    with socket.create_connection(("127.0.0.1", running.port)) as sock:
        sock.sendall(b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
        answer = read_until(sock, b"\xff" * 64)
    assert answer.startswith(b"HTTP/1.1 426 Upgrade Required")
    with socket.create_connection(("127.0.0.1", running.port)) as sock:
        sock.sendall(b"\x16\x03\x01 not HTTP at all\r\n\r\n")
        assert read_until(sock, b"\xff" * 64) == b""  # closed, nothing said
    with connect(running.url) as ws:
        ws.send(json.dumps({"op": "set_level", "level": "info"}))
        assert status_text(ws) == "Status level set to info"


def test_clients_come_and_go_and_a_closing_bridge_says_going_away(master: str) -> None:
    bridge, lines = start_bridge(master, rosapi=False)
    try:
        url = f"ws://127.0.0.1:{bridge.port}"
        with connect(url) as first:
            first.send(json.dumps({"op": "set_level", "level": "info"}))
            assert status_text(first) == "Status level set to info"
        with connect(url) as ws:
            ws.send(json.dumps({"op": "set_level", "level": "info"}))
            assert status_text(ws) == "Status level set to info"
            bridge.shutdown("test over")
            with pytest.raises(ConnectionClosed) as closed:
                ws.recv(timeout=10)
    finally:
        bridge.shutdown("test over")
    assert closed.value.rcvd is not None
    assert closed.value.rcvd.code == 1001
    assert lines[:4] == [
        f"Rosbridge WebSocket server started at ws://127.0.0.1:{bridge.port}",
        "Client connected.  1 clients total.",
        "Client disconnected. 0 clients total.",
        "Client connected.  1 clients total.",
    ]
