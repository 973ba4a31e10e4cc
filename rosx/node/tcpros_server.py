"""A node's TCPROS server: one listening port for all its topics and services (ROS/TCPROS).

As in rospy and roscpp, the connection header says what a connection is for: a ``topic`` field
makes it a subscriber, a ``service`` field a service client (`rosx.wire.tcpros.connection_kind`).
The server reads the header (bounded in size and time), then hands the socket, the decoded
header and the `FrameReader` holding any bytes that followed it to the node's handler. A header
that does not parse, names neither a topic nor a service, or that the handler refuses gets an
``error=`` header and a closed socket; the server goes on serving everyone else.

The same server can also listen on a Unix socket (`start_unix`, for `rosx.node.unixros`):
connections there go through the same handshake and the same handler.
"""

from __future__ import annotations

import asyncio
import contextlib
import socket
from typing import TYPE_CHECKING

from rosx.node import unixros
from rosx.wire.errors import ProtocolError
from rosx.wire.framing import DEFAULT_MAX_HEADER_SIZE, FrameReader
from rosx.wire.header import decode_header, encode_header
from rosx.wire.tcpros import NO_TOPIC_OR_SERVICE, connection_kind

if TYPE_CHECKING:
    from collections.abc import Awaitable, Callable

    from rosx.transport.loop_thread import LoopThread

    #: ``await handler(kind, sock, header, reader)`` → an error text to refuse, or ``None``
    #: once it has taken the socket over.
    Handler = Callable[[str, socket.socket, dict[str, str], FrameReader], Awaitable[str | None]]

#: A peer has this long to send its whole header.
HEADER_TIMEOUT = 30.0
#: Seconds before listening again after an accept failed (out of file descriptors, say).
ACCEPT_PAUSE = 0.05


class TcprosServer:
    """Accepts TCPROS connections for one node and dispatches them by their header."""

    def __init__(self, io: LoopThread, handler: Handler) -> None:
        self._io = io
        self._handler = handler
        self._sock: socket.socket | None = None
        self._unix: socket.socket | None = None
        #: The Unix socket's address (``@name``), once listening there.
        self.unix_address: str | None = None
        self._tasks: set[asyncio.Task[None]] = set()
        self.port = 0

    def start(self, bind: str, port: int = 0) -> int:
        """Listen on ``bind``:``port`` (0 picks a free port); returns the port. On the loop."""
        family = socket.AF_INET6 if ":" in bind else socket.AF_INET
        sock = socket.socket(family, socket.SOCK_STREAM)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind((bind, port))
        sock.listen(128)
        sock.setblocking(False)
        self._sock = sock
        self.port = sock.getsockname()[1]
        self._listen(sock)
        return self.port

    def start_unix(self, address: str) -> None:
        """Listen on the abstract Unix socket ``address`` too (`rosx.node.unixros`). On the loop."""
        sock = unixros.listen(address)
        self._unix = sock
        self.unix_address = address
        self._listen(sock)

    def _spawn(self, coro: Awaitable[None]) -> None:
        task: asyncio.Task[None] = self._io.loop.create_task(coro)  # type: ignore[arg-type]
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)

    # Accepting is a reader callback of the loop, not a task awaiting `loop.sock_accept`: a
    # connection that arrives as the server closes would then complete an accept whose
    # future was cancelled, and asyncio prints that error's traceback (CPython 3.10-3.13).

    def _listen(self, listener: socket.socket) -> None:
        self._io.loop.add_reader(listener.fileno(), self._accept, listener)

    def _accept(self, listener: socket.socket) -> None:
        """Take every connection waiting on ``listener``. On the loop."""
        while listener.fileno() >= 0:
            try:
                sock, _ = listener.accept()
            except (BlockingIOError, InterruptedError):
                return
            except OSError:
                # Out of file descriptors, say: listen again a little later, do not spin.
                self._io.loop.remove_reader(listener.fileno())
                self._io.loop.call_later(ACCEPT_PAUSE, self._resume, listener)
                return
            sock.setblocking(False)
            self._spawn(self._handshake(sock))

    def _resume(self, listener: socket.socket) -> None:
        if listener.fileno() >= 0:
            self._listen(listener)

    async def _handshake(self, sock: socket.socket) -> None:
        reader = FrameReader(DEFAULT_MAX_HEADER_SIZE)
        try:
            header = await asyncio.wait_for(self._read_header(sock, reader), HEADER_TIMEOUT)
        except (ProtocolError, UnicodeDecodeError) as exc:
            await self._refuse(sock, f"invalid connection header: {exc}")
            return
        except (OSError, TimeoutError, asyncio.TimeoutError, EOFError):
            sock.close()
            return
        except asyncio.CancelledError:
            sock.close()
            return
        kind = connection_kind(header)
        if kind is None:
            await self._refuse(sock, NO_TOPIC_OR_SERVICE)
            return
        try:
            error = await self._handler(kind, sock, header, reader)
        except Exception as exc:  # refuse this peer, keep serving the others
            error = f"internal error handling the connection: {exc}"
        if error is not None:
            await self._refuse(sock, error)

    async def _read_header(self, sock: socket.socket, reader: FrameReader) -> dict[str, str]:
        loop = self._io.loop
        while True:
            data = await loop.sock_recv(sock, 65536)
            if not data:
                raise EOFError
            reader.feed(data)
            block = reader.next_frame()
            if block is not None:
                return decode_header(block)

    async def _refuse(self, sock: socket.socket, reason: str) -> None:
        with contextlib.suppress(OSError):
            await asyncio.wait_for(
                self._io.loop.sock_sendall(sock, encode_header({"error": reason})), 5.0
            )
        sock.close()

    def close(self) -> None:
        """Stop listening and drop connections still in their handshake. On the loop."""
        for listener in (self._sock, self._unix):
            if listener is not None and listener.fileno() >= 0:
                self._io.loop.remove_reader(listener.fileno())
                listener.close()
        self._sock = self._unix = None
        for task in list(self._tasks):
            task.cancel()
