"""The WebSocket server both bridges stand on: sockets, handshakes and connections, on the loop.

`websockets` provides the protocol, sans-I/O (`websockets.server.ServerProtocol`: its
documented ``receive_data``/``events_received``/``data_to_send``, ``accept``/``reject``/
``send_response``, ``send_close``, ``fail``, ``state``); this shell owns the sockets, so that a
message can be written by the thread that has it (`rosx.bridge.connection`) and connections
are accepted as every rosx server accepts them (`rosx.transport.descriptors`): near the
process's descriptor limit, the oldest idle connections of the process are closed to keep
serving. A WebSocket connection is idle while its handshake is not complete, and while the
client subscribes to nothing, serves nothing and has nothing waiting (`Handler.idle`), since
it last sent anything; it is closed with code 1013 (try again later).

What a server does with its connections is a `Handler`: the rosbridge server
(`rosx.bridge.server`) and the Foxglove server (`rosx.bridge.foxglove_server`).
"""

from __future__ import annotations

import threading
from concurrent.futures import ThreadPoolExecutor
from typing import TYPE_CHECKING, Any, Generic, Protocol, TypeVar

from websockets.server import ServerProtocol

from rosx.bridge.connection import Connection
from rosx.transport import descriptors

if TYPE_CHECKING:
    import asyncio
    import socket
    from collections.abc import Callable, Iterator, Sequence

    from websockets.http11 import Request

    from rosx.bridge.ops import Frame, Pieces

S = TypeVar("S")

#: The close code of a connection closed to free a file descriptor ("try again later").
TRY_AGAIN_LATER = 1013
#: The close code of the connections a closing server ends ("going away").
GOING_AWAY = 1001


class Handler(Protocol[S]):
    """What a server does with its connections; ``S`` is its protocol core's session."""

    def refuse(self, request: Request) -> tuple[int, str] | None:
        """An HTTP status and text refusing ``request``, or None to accept it (on the loop)."""

    def session(self, connection: Connection[S]) -> S:
        """A new session for ``connection``, whose ``request`` was accepted (on the loop)."""

    def opened(self, connection: Connection[S]) -> None:
        """``connection`` is open (on the loop, before its first message)."""

    def receive(self, connection: Connection[S], data: str | bytes) -> None:
        """A message of ``connection`` (on a worker; one connection's in order)."""

    def closed(self, connection: Connection[S]) -> None:
        """``connection`` has closed (on a worker, after its last message)."""

    def render(self, session: S, message: Any) -> list[Frame | Pieces]:
        """The frames of a queued message (any thread, under the connection's lock)."""

    def oversized(self, session: S, reason: str) -> Frame | None:
        """A frame telling why a message over the size limit ends the connection (``reason``:
        the close frame's), or None."""

    def idle(self, session: S) -> bool:
        """Whether the session waits for nothing (it may be closed if descriptors run short)."""


class WebSocketServer(Generic[S]):
    """Serve ``handler``'s WebSocket connections on ``host``:``port`` (0: any free port).

    Args:
        loop: The loop the server runs on (the process's, `rosx.transport.loop_thread`).
        handler: What to do with the connections.
        max_message: The largest message a client may send, in bytes.
        subprotocols: The subprotocols offered, most preferred first.
        workers: Threads handling the clients' messages.
        name: The workers' name.
    """

    def __init__(
        self,
        loop: asyncio.AbstractEventLoop,
        handler: Handler[S],
        *,
        host: str,
        port: int,
        max_message: int,
        subprotocols: Sequence[str] = (),
        workers: int = 8,
        name: str = "rosx-websocket",
    ) -> None:
        self.loop = loop
        self.handler = handler
        self.host = host
        self.port = port
        self.max_message = max_message
        self.subprotocols = tuple(subprotocols)
        self.pool = ThreadPoolExecutor(workers, thread_name_prefix=name)
        self._open: set[Connection[S]] = set()  # under _lock: the loop adds, any thread reads
        self._all: set[Connection[S]] = set()
        self._lock = threading.Lock()
        self._listener: descriptors.Listener | None = None

    @property
    def connections(self) -> set[Connection[S]]:
        """The open connections (a copy; any thread)."""
        with self._lock:
            return set(self._open)

    def protocol(self) -> ServerProtocol:
        """A new connection's protocol object."""
        return ServerProtocol(
            subprotocols=self.subprotocols or None,  # type: ignore[arg-type]
            max_size=self.max_message,
        )

    def start(self) -> None:
        """Bind and listen (on the loop); `port` is then the bound port.

        Raises:
            OSError: the address cannot be bound (``errno.EADDRINUSE``: the port is taken).
        """
        listener = descriptors.Listener(self.loop, self._accepted)
        for sock in descriptors.tcp_listeners(self.host, self.port):
            listener.listen(sock)
        self._listener = listener
        self.port = listener.sockets[0].getsockname()[1]
        descriptors.watch(self)

    def close(self) -> None:
        """Stop listening and close every connection (on the loop)."""
        descriptors.forget(self)
        if self._listener is not None:
            self._listener.close()
        for connection in list(self._all):
            connection.abort(GOING_AWAY, "the server is closing")
        self.pool.shutdown(wait=False, cancel_futures=True)

    def _accepted(self, sock: socket.socket) -> None:
        connection = Connection(self, sock)
        self._all.add(connection)
        connection.start()

    def opened(self, connection: Connection[S]) -> None:
        """Called by ``connection`` when its handshake has succeeded (on the loop)."""
        with self._lock:
            self._open.add(connection)
        self.handler.opened(connection)

    def forget(self, connection: Connection[S]) -> bool:
        """Called by ``connection`` when it has closed; whether it had been open."""
        self._all.discard(connection)
        with self._lock:
            was_open = connection in self._open
            self._open.discard(connection)
        return was_open

    def idle_connections(self) -> Iterator[tuple[float, Callable[[], object]]]:
        """Connections waiting for nothing, with when their clients last sent anything: what
        `rosx.transport.descriptors` may close when descriptors run short (on the loop)."""
        for connection in list(self._all):
            if connection.session is None or (
                not connection.busy() and self.handler.idle(connection.session)
            ):
                yield connection.since, _closer(connection)


def _closer(connection: Connection[Any]) -> Callable[[], object]:
    return lambda: connection.abort(TRY_AGAIN_LATER, "the server is short of file descriptors")


__all__ = ["GOING_AWAY", "TRY_AGAIN_LATER", "Handler", "WebSocketServer"]
