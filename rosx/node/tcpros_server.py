"""A node's TCPROS server: one listening port for all its topics and services (ROS/TCPROS).

As in rospy and roscpp, the connection header says what a connection is for: a ``topic`` field
makes it a subscriber, a ``service`` field a service client (`rosx.wire.tcpros.connection_kind`).
The server reads the header (bounded in size and time), then hands the socket, the decoded
header and the `FrameReader` holding any bytes that followed it to the node's handler. A header
that does not parse, names neither a topic nor a service, or that the handler refuses gets an
``error=`` header and a closed socket; the server goes on serving everyone else.

The same server can also listen on a Unix socket (`start_unix`, for `rosx.node.unixros`):
connections there go through the same handshake and the same handler.

Connections still waiting for their header are the idle ones `rosx.transport.descriptors` may
close, oldest first, when the process runs short of file descriptors.
"""

from __future__ import annotations

import asyncio
import contextlib
import socket
from typing import TYPE_CHECKING

from rosx.node import unixros
from rosx.transport import descriptors
from rosx.wire.errors import ProtocolError
from rosx.wire.framing import DEFAULT_MAX_HEADER_SIZE, FrameReader
from rosx.wire.header import decode_header, encode_header
from rosx.wire.tcpros import NO_TOPIC_OR_SERVICE, connection_kind

if TYPE_CHECKING:
    from collections.abc import Awaitable, Callable, Iterator

    from rosx.transport.loop_thread import LoopThread

    #: ``await handler(kind, sock, header, reader)`` → an error text to refuse, or ``None``
    #: once it has taken the socket over.
    Handler = Callable[[str, socket.socket, dict[str, str], FrameReader], Awaitable[str | None]]

#: A peer has this long to send its whole header.
HEADER_TIMEOUT = 30.0


class TcprosServer:
    """Accepts TCPROS connections for one node and dispatches them by their header."""

    def __init__(self, io: LoopThread, handler: Handler) -> None:
        self._io = io
        self._handler = handler
        self._listener: descriptors.Listener | None = None
        #: The Unix socket's address (``@name``), once listening there.
        self.unix_address: str | None = None
        self._tasks: set[asyncio.Task[None]] = set()
        # Handshakes still waiting for their header, with when they began.
        self._waiting: dict[asyncio.Task[None], float] = {}
        self.port = 0

    def start(self, bind: str, port: int = 0) -> int:
        """Listen on ``bind``:``port`` (0 picks a free port); returns the port. On the loop."""
        family = socket.AF_INET6 if ":" in bind else socket.AF_INET
        sock = socket.socket(family, socket.SOCK_STREAM)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind((bind, port))
        sock.listen(descriptors.BACKLOG)
        sock.setblocking(False)
        self.port = sock.getsockname()[1]
        self._listen(sock)
        return self.port

    def start_unix(self, address: str) -> None:
        """Listen on the abstract Unix socket ``address`` too (`rosx.node.unixros`). On the loop."""
        self._listen(unixros.listen(address))
        self.unix_address = address

    def _listen(self, sock: socket.socket) -> None:
        if self._listener is None:
            self._listener = descriptors.Listener(self._io.loop, self._accepted)
            descriptors.watch(self)
        self._listener.listen(sock)

    def _spawn(self, coro: Awaitable[None]) -> None:
        task: asyncio.Task[None] = self._io.loop.create_task(coro)  # type: ignore[arg-type]
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)

    def _accepted(self, sock: socket.socket) -> None:
        self._spawn(self._handshake(sock))

    def idle_connections(self) -> Iterator[tuple[float, Callable[[], object]]]:
        """Connections that have not sent their header yet, with when they were accepted:
        what `rosx.transport.descriptors` may close when descriptors run short."""
        for task, since in self._waiting.items():
            yield since, task.cancel

    async def _handshake(self, sock: socket.socket) -> None:
        reader = FrameReader(DEFAULT_MAX_HEADER_SIZE)
        task = asyncio.current_task()
        assert task is not None
        self._waiting[task] = self._io.loop.time()
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
        finally:
            self._waiting.pop(task, None)
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
        descriptors.forget(self)
        if self._listener is not None:
            self._listener.close()
        for task in list(self._tasks):
            task.cancel()
