"""The node's TCPROS server on its own: accepting connections, and closing with one arriving."""

from __future__ import annotations

import asyncio
import logging
import socket
from typing import TYPE_CHECKING, TypeVar

import pytest

from rosx.node.tcpros_server import TcprosServer
from rosx.transport.loop_thread import LoopThread
from rosx.wire.header import encode_header
from tests.support.procs import wait_for

if TYPE_CHECKING:
    from collections.abc import Callable, Iterator

    from rosx.wire.framing import FrameReader

T = TypeVar("T")


class Taker:
    """A handler that takes every connection over, keeping its socket and header."""

    def __init__(self) -> None:
        self.taken: list[tuple[str, dict[str, str]]] = []
        self.socks: list[socket.socket] = []

    async def __call__(
        self, kind: str, sock: socket.socket, header: dict[str, str], reader: FrameReader
    ) -> str | None:
        self.taken.append((kind, header))
        self.socks.append(sock)
        return None

    def close(self) -> None:
        for sock in self.socks:
            sock.close()


@pytest.fixture
def taker() -> Iterator[Taker]:
    handler = Taker()
    try:
        yield handler
    finally:
        handler.close()


def on_loop(io: LoopThread, call: Callable[[], T]) -> T:
    """``call()`` run on the loop's thread; its result."""

    async def run() -> T:
        return call()

    return io.run(run(), timeout=10)


async def turns(count: int) -> None:
    """Let the loop run ``count`` more turns."""
    for _ in range(count):
        await asyncio.sleep(0)


def test_every_waiting_connection_is_taken_over(io: LoopThread, taker: Taker) -> None:
    server = TcprosServer(io, taker)
    port = on_loop(io, lambda: server.start("127.0.0.1"))
    clients = [socket.create_connection(("127.0.0.1", port), timeout=10) for _ in range(3)]
    try:
        for number, client in enumerate(clients):
            client.sendall(encode_header({"topic": f"/t{number}", "callerid": "/c"}))
        wait_for(lambda: len(taker.taken) == 3, what="three connections taken over")
        assert sorted(header["topic"] for _, header in taker.taken) == ["/t0", "/t1", "/t2"]
        assert {kind for kind, _ in taker.taken} == {"topic"}
    finally:
        on_loop(io, server.close)
        for client in clients:
            client.close()


def test_a_connection_arriving_as_the_server_closes_is_dropped_quietly(
    io: LoopThread, taker: Taker, caplog: pytest.LogCaptureFixture
) -> None:
    # A node shutting down as /rosout connects to it: in one turn of the loop the listening
    # socket is readable and `close` runs before the accept can.
    server = TcprosServer(io, taker)
    port = on_loop(io, lambda: server.start("127.0.0.1"))
    client = socket.socket()
    client.settimeout(10)

    def connect_then_close() -> None:
        client.connect(("127.0.0.1", port))  # completes in the listener's backlog
        io.loop.call_soon(server.close)

    caplog.set_level(logging.DEBUG, logger="asyncio")
    try:
        on_loop(io, connect_then_close)
        # A few more turns of the loop, for anything the close left scheduled.
        io.run(turns(5), timeout=10)
        assert [r.getMessage() for r in caplog.records if r.levelno >= logging.ERROR] == []
        assert taker.taken == []
        # The connection never accepted is reset with the listener.
        with pytest.raises(ConnectionResetError):
            client.sendall(b"x" * 4)
            client.recv(1)
    finally:
        client.close()
