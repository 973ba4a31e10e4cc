"""Service servers that misbehave on purpose, registered with a master like real ones.

`FakeServices` listens on a free port and answers each connection by the service it names:

* ``refuse_empty``: ok byte 0 with an empty text, as roscpp answers when a handler returns false;
* ``close_mid_call``: reads the request, then closes without answering (a server dying mid-call);
* ``silent``: reads the request and never answers (until the fake is closed).

Every service answers probes with a header naming ``std_srvs/Empty``. `register` puts a service
on the master as node ``/fake``; `register_dead` registers one at a port where nothing listens.
"""

from __future__ import annotations

import contextlib
import socket
import threading
from typing import Any

from rosx.msg.codec.classes import get_service_class
from rosx.transport.client import XmlRpcClient
from rosx.wire.framing import FrameReader
from rosx.wire.header import decode_header, encode_header
from rosx.wire.rosrpc import ServiceInfo, encode_error, format_rosrpc_uri, server_header
from tests.support.procs import free_port

EMPTY = get_service_class("std_srvs/Empty")
FAKE_NODE = "/fake"
FAKE_API = "http://127.0.0.1:9/"


class FakeServices:
    """A misbehaving service server on a thread of its own; close it when done."""

    def __init__(self) -> None:
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.uri = format_rosrpc_uri("127.0.0.1", self.port)
        self.closed = threading.Event()
        self.connections: list[socket.socket] = []
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self) -> None:
        while not self.closed.is_set():
            try:
                sock, _ = self.listener.accept()
            except OSError:
                return
            self.connections.append(sock)
            threading.Thread(target=self._answer, args=(sock,), daemon=True).start()

    def _answer(self, sock: socket.socket) -> None:
        reader = FrameReader()
        with contextlib.suppress(OSError):
            header = self._next(sock, reader)
            if header is None:
                return
            fields = decode_header(header)
            name = fields.get("service", "")
            info = ServiceInfo(
                name, EMPTY._type, EMPTY._md5sum, "std_srvs/EmptyRequest", "std_srvs/EmptyResponse"
            )
            sock.sendall(encode_header(server_header(info, callerid=FAKE_NODE)))
            if fields.get("probe") == "1" or self._next(sock, reader) is None:
                return
            behaviour = name.rsplit("/", 1)[-1]
            if behaviour == "refuse_empty":
                sock.sendall(encode_error(""))
            elif behaviour == "silent":
                self.closed.wait()
        with contextlib.suppress(OSError):
            sock.close()

    @staticmethod
    def _next(sock: socket.socket, reader: FrameReader) -> bytes | None:
        while True:
            frame = reader.next_frame()
            if frame is not None:
                return frame
            data = sock.recv(65536)
            if not data:
                return None
            reader.feed(data)

    def register(self, master_uri: str, name: str) -> None:
        """Register ``name`` on the master as served here by node ``/fake``."""
        _call(master_uri, "registerService", name, self.uri)

    def close(self) -> None:
        self.closed.set()
        self.listener.close()
        for sock in self.connections:
            with contextlib.suppress(OSError):
                sock.close()
        self.thread.join(5)


def register_dead(master_uri: str, name: str) -> None:
    """Register ``name`` at a port where no server listens (a service whose node died)."""
    _call(master_uri, "registerService", name, format_rosrpc_uri("127.0.0.1", free_port()))


def _call(master_uri: str, method: str, *params: Any) -> None:
    client = XmlRpcClient(timeout=5.0)
    try:
        code, status, _ = client.call(master_uri, method, FAKE_NODE, *params, FAKE_API)
    finally:
        client.close()
    assert code == 1, status
