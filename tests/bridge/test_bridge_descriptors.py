"""Idle WebSocket connections cannot starve the bridge of file descriptors: with more of them on
its rosbridge and Foxglove ports than its descriptor limit (connections that completed the
handshake and then asked for nothing, and connections that never sent one), a new client of
either protocol is still served.

The bridge (with a core and a latching talker) runs in a process of its own limited to `LIMIT`
descriptors; only closing the oldest idle connections early can make room.
"""

from __future__ import annotations

import json
import select
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence

from websockets.sync.client import connect
from websockets.typing import Subprotocol

from tests.support.cli import clean_environ
from tests.support.procs import running, wait_for
from tests.support.reserve import IDLE_WARNING, enough_descriptors, idle_connections

LIMIT = 256
ROSBRIDGE_IDLE, FOXGLOVE_IDLE, NO_HANDSHAKE = 140, 70, 70

BRIDGE = f"""
import resource, sys, threading
resource.setrlimit(resource.RLIMIT_NOFILE, ({LIMIT}, {LIMIT}))
from rosx.bridge.app import Bridge, BridgeOptions
from rosx.core import Core
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
String = get_message_class("std_msgs/String")
with Core(0, {{}}) as core:
    node = Node("/talker", master_uri=core.uri, environ={{}}).start()
    node.advertise("/chatter", String, latch=True).publish(String(data="still here"))
    options = BridgeOptions(port=0, foxglove_port=0, rosapi=False, master_uri=core.uri, environ={{}})
    bridge = Bridge(options, log=lambda line: print(line, file=sys.stderr)).start()
    assert bridge.foxglove is not None
    print(bridge.port, bridge.foxglove.port, flush=True)
    threading.Event().wait()
"""


def handshake(protocol: str = "") -> bytes:
    offer = f"Sec-WebSocket-Protocol: {protocol}\r\n" if protocol else ""
    return (
        "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
        f"Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n{offer}\r\n"
    ).encode()


def open_websockets(sockets: Sequence[socket.socket], request: bytes) -> None:
    """Send the handshake on each of ``sockets`` and wait for every answer."""
    for sock in sockets:
        sock.sendall(request)
    waiting = {sock.fileno(): sock for sock in sockets}
    answers = dict.fromkeys(waiting, b"")
    poller = select.poll()
    for fd in waiting:
        poller.register(fd, select.POLLIN)
    deadline = time.monotonic() + 30
    while waiting and time.monotonic() < deadline:
        for fd, _ in poller.poll(100):
            chunk = waiting[fd].recv(4096)
            answers[fd] += chunk
            if not chunk or b"\r\n\r\n" in answers[fd]:
                poller.unregister(fd)
                del waiting[fd]
    assert not waiting, f"{len(waiting)} handshakes unanswered"


def ended(sock: socket.socket) -> bool:
    """Whether the bridge has closed ``sock`` (what it sent before is read and dropped)."""
    try:
        while sock.recv(65536, socket.MSG_DONTWAIT):
            pass
    except BlockingIOError:
        return False
    except OSError:
        return True
    return True


def test_bridge_serves_beside_more_idle_connections_than_descriptors() -> None:
    with (
        enough_descriptors(2 * LIMIT + 200),
        tempfile.TemporaryFile() as log,
        running(
            [sys.executable, "-c", BRIDGE], clean_environ(), stdout=subprocess.PIPE, stderr=log
        ) as bridge,
    ):
        assert bridge.stdout is not None
        ports = bridge.stdout.readline().decode().split()
        rosbridge, foxglove = (("127.0.0.1", int(port)) for port in ports)
        with (
            idle_connections(rosbridge, ROSBRIDGE_IDLE) as on_rosbridge,
            idle_connections(foxglove, FOXGLOVE_IDLE) as on_foxglove,
        ):
            open_websockets(on_rosbridge, handshake())
            open_websockets(on_foxglove, handshake("foxglove.websocket.v1"))
            with idle_connections(rosbridge, NO_HANDSHAKE) as silent:
                everyone = [*on_rosbridge, *on_foxglove, *silent]
                # More idle connections than the bridge could hold have been closed, the
                # oldest first: those of the rosbridge port that were opened first.
                wait_for(
                    lambda: sum(map(ended, everyone)) >= len(everyone) - LIMIT,
                    timeout=60,
                    what="idle connections to be closed",
                )
                assert ended(on_rosbridge[0])
                with connect(f"ws://{rosbridge[0]}:{rosbridge[1]}") as ws:
                    ws.send(json.dumps({"op": "subscribe", "topic": "/chatter"}))
                    message = json.loads(ws.recv(timeout=10))
                assert message["msg"] == {"data": "still here"}
                offer = [Subprotocol("foxglove.websocket.v1")]
                with connect(f"ws://{foxglove[0]}:{foxglove[1]}", subprotocols=offer) as fox:
                    assert json.loads(fox.recv(timeout=10))["op"] == "serverInfo"
        log.seek(0)
        lines = log.read().decode().splitlines()
    assert len([line for line in lines if IDLE_WARNING in line]) == 1
    assert not [line for line in lines if "Traceback" in line]
