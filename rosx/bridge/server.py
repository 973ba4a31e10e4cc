"""The rosbridge WebSocket server: rosbridge v2 sessions over `rosx.bridge.websocket`.

Each connection gets a `Session` (the protocol, `rosx.bridge.protocol`); its frames are handed,
in order, to `GraphSide.receive` on a worker thread (the node runtime's calls block), and what
the graph sends it waits in the connection's bounded queues (`rosx.bridge.connection`).

Before the WebSocket handshake completes, the page's ``Origin`` is checked against the
allow-list (`rosx.bridge.safety`); a foreign page gets HTTP 403. A frame over the size limit
closes the connection with code 1009, after a status saying why (the protocol refuses it from
its header, before reading the payload).
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any
from urllib.parse import parse_qs, urlsplit

from rosx.bridge.protocol import DEFAULT_MAX_MESSAGE, Session
from rosx.bridge.safety import origin_allowed, refusal, refusal_answer
from rosx.bridge.websocket import WebSocketServer

if TYPE_CHECKING:
    from collections.abc import Sequence

    from websockets.http11 import Request

    from rosx.bridge import ops
    from rosx.bridge.connection import Connection
    from rosx.bridge.graph_side import GraphSide
    from rosx.bridge.outgoing import Outgoing

#: Threads handling clients' requests (each client's in order).
REQUEST_WORKERS = 32


class BridgeServer:
    """The rosbridge v2 WebSocket server over ``graph`` on the graph node's event loop.

    Args:
        graph: The graph side every client shares.
        host: The address to bind (loopback unless told otherwise).
        port: The port (0: any free one; see `port` once started).
        allow_origins: Origin patterns allowed besides this machine's pages.
        token: The secret clients must show (``auth`` op or ``?token=``), or None.
        max_message: The largest frame a client may send, in bytes.
        log: Where connection lines go (``print`` by default).
    """

    def __init__(
        self,
        graph: GraphSide,
        *,
        host: str = "127.0.0.1",
        port: int = 9090,
        allow_origins: Sequence[str] = (),
        token: str | None = None,
        max_message: int = DEFAULT_MAX_MESSAGE,
        log: Callable[[str], object] = print,
    ) -> None:
        self.graph = graph
        self.host = host
        self.port = port
        self.allow_origins = tuple(allow_origins)
        self.token = token
        self.max_message = max_message
        self.log = log
        self._server: WebSocketServer[Session] | None = None

    @property
    def connections(self) -> set[Connection[Session]]:
        """The open connections."""
        return set() if self._server is None else self._server.connections

    async def start(self) -> None:
        """Bind and start serving (on the loop); `port` is then the bound port."""
        import asyncio  # noqa: PLC0415 - the running loop, for the server

        self._server = WebSocketServer(
            asyncio.get_running_loop(),
            self,
            host=self.host,
            port=self.port,
            max_message=self.max_message,
            workers=REQUEST_WORKERS,
            name="rosx-bridge",
        )
        self._server.start()
        self.port = self._server.port

    async def close(self) -> None:
        """Close every connection and stop listening."""
        if self._server is not None:
            self._server.close()

    # -- the `Handler` ---------------------------------------------------------------------------

    def refuse(self, request: Request) -> tuple[int, str] | None:
        """Refuse a page of an origin not allowed (403, logged, with the ``--allow-origin`` that
        would let it in); else None. The token is checked later, by the session."""
        origin = request.headers.get("Origin")
        if origin_allowed(origin, self.allow_origins):
            return None
        self.log(refusal(origin))
        return 403, refusal_answer(origin)

    def session(self, connection: Connection[Session]) -> Session:
        """A rosbridge session, already authenticated when the URL carries the bridge's token
        (else its first op must be ``auth``), limited to ``max_message`` bytes."""
        token = self.token
        path = connection.request.path if connection.request is not None else ""
        if token is not None and token in parse_qs(urlsplit(path).query).get("token", []):
            token = None
        address: Any = connection.remote_address
        host = str(address[0]) if address else ""
        return Session(token=token, max_message=self.max_message, client=host)

    def opened(self, connection: Connection[Session]) -> None:
        """Log the client count, as rosbridge_server does."""
        self.log(f"Client connected.  {len(self.connections)} clients total.")

    def receive(self, connection: Connection[Session], data: str | bytes) -> None:
        """Pass the client's message to the shared graph, which runs its ops in order."""
        self.graph.receive(connection, data)

    def closed(self, connection: Connection[Session]) -> None:
        """Drop what the client held in the graph, log the messages it was too slow to get, and
        the client count."""
        self.graph.disconnect(connection)
        for topic, count in sorted(connection.dropped.items()):
            self.log(
                f"Client was sent {count} messages fewer on {topic}: it read slower than "
                "they came (its oldest were dropped)"
            )
        self.log(f"Client disconnected. {len(self.connections)} clients total.")

    def render(self, session: Session, message: Outgoing) -> list[ops.Frame | ops.Pieces]:
        """The frames of one outgoing message (throttled, queued and compressed per
        subscription)."""
        return session.deliver(message, time.monotonic())

    def oversized(self, session: Session, reason: str) -> ops.Frame | None:
        """A ``status`` op naming the size limit (``--max-message-size``), sent before closing."""
        limit = self.max_message
        text = f"Message refused ({reason}): the limit is {limit} bytes (--max-message-size)"
        return json.dumps({"op": "status", "level": "error", "msg": text})

    def idle(self, session: Session) -> bool:
        """Whether the client neither subscribes nor provides services (so it may be closed
        first)."""
        return not session.topics and not session.services


__all__ = ["BridgeServer"]
