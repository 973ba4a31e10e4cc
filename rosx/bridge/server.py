"""The rosbridge WebSocket server: the shell that moves the core's frames over `websockets`.

Each connection gets a `Session` (the protocol, `rosx.bridge.protocol`) and a `Connection`
(its queues). Frames from the client are handed, in order, to `GraphSide.receive` on a worker
thread (the node runtime's calls block). Frames to the client wait in bounded queues: one for
statuses and service frames, one per subscribed topic holding at most the subscription's
``queue_length`` messages (or the server's default); when a topic's queue is full its oldest
message is dropped and counted, so a slow client never holds up the others or grows the
server's memory. A writer task per connection sends, taking topics in turn.

Before the WebSocket handshake completes, the page's ``Origin`` is checked against the
allow-list (`rosx.bridge.safety`); a foreign page gets HTTP 403. A frame over the size limit
closes the connection with code 1009, after a status saying why (the library refuses it from
its header, before reading the payload).
"""

from __future__ import annotations

import asyncio
import json
import threading
import time
from collections import deque
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import TYPE_CHECKING, Any, Generic, TypeVar
from urllib.parse import parse_qs, urlsplit

from websockets.asyncio.server import ServerConnection, serve
from websockets.exceptions import ConnectionClosed
from websockets.protocol import State

from rosx.bridge.protocol import DEFAULT_MAX_MESSAGE, Session
from rosx.bridge.safety import origin_allowed, refusal

if TYPE_CHECKING:
    from collections.abc import Sequence

    from websockets.asyncio.server import Server
    from websockets.http11 import Request, Response

    from rosx.bridge import ops
    from rosx.bridge.graph_side import GraphSide
    from rosx.bridge.outgoing import Outgoing

#: Control frames (statuses, service calls and answers) a client may have waiting.
MAX_CONTROL = 10_000
#: The most frames, and about the most bytes, written to a client's socket in one go.
BATCH_FRAMES = 64
BATCH_BYTES = 256 << 10
#: The bytes buffered for a client before sending waits for its socket.
WRITE_LIMIT = 4 << 20
#: Threads handling clients' requests (each client's in order).
REQUEST_WORKERS = 32


S = TypeVar("S")


class Connection(Generic[S]):
    """One client: its session (a protocol's core), its queues and its writer. Thread-safe
    where `rosx.bridge.graph_side.Client` says; the session is used under ``lock``.

    The queues are filled from any thread under ``_queues``; the loop is woken once per
    burst (``_signalled``), not once per message, so a fast topic costs the loop no wake-up
    per message while the writer is busy.
    """

    def __init__(
        self,
        ws: ServerConnection,
        session: S,
        loop: asyncio.AbstractEventLoop,
        render: Callable[[S, Any], list[ops.Frame]],
    ) -> None:
        self.ws = ws
        self.session = session
        self.render = render
        self.lock = threading.Lock()
        self.loop = loop
        self.control: deque[list[ops.Frame]] = deque()
        self.topics: dict[str, deque[Any]] = {}
        self.turns: deque[str] = deque()
        self.dropped: dict[str, int] = {}
        self.wake = asyncio.Event()
        self.closing: tuple[int, str] | None = None
        self._queues = threading.Lock()
        self._signalled = False

    # -- the `Client` protocol (any thread) ----------------------------------------------------

    def send(self, frames: list[ops.Frame]) -> None:
        with self._queues:
            if len(self.control) < MAX_CONTROL:
                self.control.append(frames)
            self._signal()

    def queue_message(self, topic: str, message: Any, bound: int) -> bool:
        dropped = False
        with self._queues:
            queue = self.topics.get(topic)
            if queue is None or queue.maxlen != max(1, bound):
                queue = self.topics[topic] = deque(queue or (), maxlen=max(1, bound))
            if len(queue) == queue.maxlen:
                self.dropped[topic] = self.dropped.get(topic, 0) + 1
                dropped = True
            elif not queue:
                self.turns.append(topic)
            queue.append(message)
            self._signal()
        return dropped

    def close(self, code: int, reason: str) -> None:
        with self._queues:
            self.closing = (code, reason)
            self._signal()

    def _signal(self) -> None:
        if not self._signalled:
            self._signalled = True
            self.loop.call_soon_threadsafe(self.wake.set)

    # -- on the loop -----------------------------------------------------------------------------

    def _next(self) -> list[ops.Frame] | None:
        with self._queues:
            if self.control:
                return self.control.popleft()
            while self.turns:
                topic = self.turns.popleft()
                queue = self.topics.get(topic)
                if not queue:
                    continue
                message = queue.popleft()
                if queue:
                    self.turns.append(topic)
                break
            else:
                self._signalled = False  # drained: the next frame wakes the writer again
                return None
        with self.lock:  # rendered here, on the loop, only if it is sent
            return self.render(self.session, message)

    async def write(self) -> None:
        """Send what waits, until the connection closes.

        What waits is written in batches (websockets' documented ``send_context``, frames
        made by its sans-I/O protocol): one write to the socket and one flow-control check
        for up to `BATCH_FRAMES` frames or `BATCH_BYTES` bytes, instead of one of each per
        frame.
        """
        protocol = self.ws.protocol
        while True:
            await self.wake.wait()
            self.wake.clear()
            try:
                more = True
                while more:
                    count = size = 0
                    async with self.ws.send_context():
                        while count < BATCH_FRAMES and size < BATCH_BYTES:
                            frames = self._next()
                            if frames is None:
                                more = False
                                break
                            for frame in frames:
                                data = frame.encode() if isinstance(frame, str) else frame
                                if isinstance(frame, str):
                                    protocol.send_text(data)
                                else:
                                    protocol.send_binary(data)
                                count += 1
                                size += len(data)
                if self.closing is not None:
                    await self.ws.close(*self.closing)
                    return
            except ConnectionClosed:
                return

    def dropped_total(self) -> int:
        """Messages dropped for this client so far, all topics together."""
        return sum(self.dropped.values())


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
        self.connections: set[Connection[Session]] = set()
        self._server: Server | None = None
        self._pool = ThreadPoolExecutor(REQUEST_WORKERS, thread_name_prefix="rosx-bridge")

    async def start(self) -> None:
        """Bind and start serving; `port` is then the bound port."""
        self._server = await serve(
            self._serve,
            self.host,
            self.port,
            process_request=self._check_request,
            max_size=self.max_message,
            compression=None,  # deflating big messages costs more than it saves on a LAN
            ping_interval=None,
            # Sends wait for the socket only past 4 MiB buffered: a big message does not stall
            # behind the previous one's last bytes.
            write_limit=WRITE_LIMIT,
        )
        sockets = list(self._server.sockets)
        self.port = sockets[0].getsockname()[1]

    async def close(self) -> None:
        """Close every connection and stop listening."""
        if self._server is not None:
            self._server.close()
            await self._server.wait_closed()
        self._pool.shutdown(wait=False, cancel_futures=True)

    def _check_request(self, ws: ServerConnection, request: Request) -> Response | None:
        origin = request.headers.get("Origin")
        if origin_allowed(origin, self.allow_origins):
            return None
        self.log(refusal(origin))
        return ws.respond(
            403,
            f"Origin {origin} is not allowed: start the bridge with --allow-origin {origin} "
            "to let its pages connect\n",
        )

    async def _serve(self, ws: ServerConnection) -> None:
        loop = asyncio.get_running_loop()
        token = self.token
        path = ws.request.path if ws.request is not None else ""
        if token is not None and token in parse_qs(urlsplit(path).query).get("token", []):
            token = None
        session = Session(token=token, max_message=self.max_message, client=_host(ws))
        connection: Connection[Session] = Connection(ws, session, loop, _render)
        _status_before_refusal(ws, self.max_message)
        self.connections.add(connection)
        self.log(f"Client connected.  {len(self.connections)} clients total.")
        writer = asyncio.create_task(connection.write())
        try:
            async for data in ws:
                await loop.run_in_executor(self._pool, self.graph.receive, connection, data)
        except ConnectionClosed:
            pass
        finally:
            writer.cancel()
            self.connections.discard(connection)
            await loop.run_in_executor(self._pool, self.graph.disconnect, connection)
            for topic, count in sorted(connection.dropped.items()):
                self.log(
                    f"Client was sent {count} messages fewer on {topic}: it read slower than "
                    "they came (its oldest were dropped)"
                )
            self.log(f"Client disconnected. {len(self.connections)} clients total.")


def _render(session: Session, message: Outgoing) -> list[ops.Frame]:
    return session.deliver(message, time.monotonic())


def _host(ws: ServerConnection) -> str:
    address: Any = ws.remote_address
    return str(address[0]) if address else ""


def _status_before_refusal(ws: ServerConnection, limit: int) -> None:
    """Send a status before websockets closes the connection with 1009 for a frame over
    ``limit``: the library fails the connection from within its sans-I/O protocol, so the
    status goes into the same outgoing buffer just ahead of the close frame."""
    protocol = ws.protocol
    fail = protocol.fail

    def fail_with_status(code: int, reason: str = "") -> None:
        if code == 1009 and protocol.state is State.OPEN:
            text = f"Message refused ({reason}): the limit is {limit} bytes (--max-message-size)"
            protocol.send_text(json.dumps({"op": "status", "level": "error", "msg": text}).encode())
        fail(code, reason)

    protocol.fail = fail_with_status  # type: ignore[method-assign]


__all__ = ["BridgeServer", "Connection"]
