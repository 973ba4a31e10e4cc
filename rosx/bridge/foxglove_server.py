"""The Foxglove WebSocket server: `rosx.bridge.foxglove`'s sessions over `rosx.bridge.websocket`.

It shares the bridge's node and the connections' bounded queues (`rosx.bridge.connection`):
one raw subscription per topic whoever subscribes, one publisher per topic clients publish.
Every `POLL_PERIOD` seconds it reads the graph (topic types, and each new service's type, probed
once) and lets each session advertise what changed. Foxglove clients send no ``Origin``
unless they are pages; pages are checked as rosbridge's are. A token, when set, must come as
``?token=`` in the URL (the protocol has no ``auth`` op); a wrong one gets HTTP 401.
"""

from __future__ import annotations

import asyncio
import contextlib
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from typing import TYPE_CHECKING, Any
from urllib.parse import parse_qs, urlsplit

from rosx.bridge import foxglove as fx
from rosx.bridge.protocol import DEFAULT_MAX_MESSAGE
from rosx.bridge.safety import origin_allowed, refusal, refusal_answer
from rosx.bridge.websocket import WebSocketServer
from rosx.graph.state import registrations
from rosx.msg.codec.classes import get_service_class

if TYPE_CHECKING:
    from collections.abc import Callable, Sequence

    from websockets.http11 import Request

    from rosx.bridge.connection import Connection
    from rosx.bridge.ops import Pieces
    from rosx.node import Node, Publisher, Subscriber
    from rosx.node.subscription import RawMessage

#: How often the graph is read for channels and services to advertise (seconds).
POLL_PERIOD = 1.0
#: Threads handling clients' requests (each client's in order).
REQUEST_WORKERS = 8


class FoxgloveServer:
    """The Foxglove WebSocket protocol over ``node`` (started, owned by the caller)."""

    def __init__(
        self,
        node: Node,
        *,
        host: str = "127.0.0.1",
        port: int = 8765,
        allow_origins: Sequence[str] = (),
        token: str | None = None,
        max_message: int = DEFAULT_MAX_MESSAGE,
        log: Callable[[str], object] = print,
    ) -> None:
        self.node = node
        self.host = host
        self.port = port
        self.allow_origins = tuple(allow_origins)
        self.token = token
        self.max_message = max_message
        self.log = log
        self._server: WebSocketServer[fx.FoxgloveSession] | None = None
        self._poller: asyncio.Task[None] | None = None
        self._pool = ThreadPoolExecutor(2, thread_name_prefix="rosx-foxglove-graph")
        self._lock = threading.Lock()
        self._subscribed: dict[str, tuple[Subscriber, set[Connection[fx.FoxgloveSession]]]] = {}
        self._published: dict[str, tuple[Publisher, set[Connection[fx.FoxgloveSession]]]] = {}
        self._service_types: dict[str, str] = {}
        self._graph: tuple[dict[str, str], dict[str, str]] = ({}, {})
        self._sim_time = False
        self._clock: Subscriber | None = None

    @property
    def connections(self) -> set[Connection[fx.FoxgloveSession]]:
        """The open connections."""
        return set() if self._server is None else self._server.connections

    async def start(self) -> None:
        """Bind, read the graph once, and start serving."""
        loop = asyncio.get_running_loop()
        self._graph = await loop.run_in_executor(self._pool, self._read_graph)
        await loop.run_in_executor(self._pool, self._follow_clock)
        self._server = WebSocketServer(
            loop,
            self,
            host=self.host,
            port=self.port,
            max_message=self.max_message,
            subprotocols=[fx.SUBPROTOCOL],
            workers=REQUEST_WORKERS,
            name="rosx-foxglove",
        )
        self._server.start()
        self.port = self._server.port
        self._poller = asyncio.create_task(self._poll())

    async def close(self) -> None:
        """Close every connection and stop listening."""
        if self._poller is not None:
            self._poller.cancel()
        if self._clock is not None:
            self._clock.unregister()
        if self._server is not None:
            self._server.close()
        self._pool.shutdown(wait=False, cancel_futures=True)

    # -- the `Handler` ---------------------------------------------------------------------------

    def refuse(self, request: Request) -> tuple[int, str] | None:
        """Refuse a page of an origin not allowed (403, logged) and, with a token set, a URL
        without ``?token=`` matching it (401); else None."""
        origin = request.headers.get("Origin")
        if not origin_allowed(origin, self.allow_origins):
            self.log(refusal(origin, "Foxglove"))
            return 403, refusal_answer(origin)
        if self.token is not None:
            tokens = parse_qs(urlsplit(request.path).query).get("token", [])
            if self.token not in tokens:
                return 401, "This bridge needs ?token=… in its URL\n"
        return None

    def session(self, connection: Connection[fx.FoxgloveSession]) -> fx.FoxgloveSession:
        """A Foxglove session named after the bridge's node, on sim time when ``/use_sim_time``
        is."""
        return fx.FoxgloveSession(name=f"rosx {self.node.name}", sim_time=self._sim_time)

    def opened(self, connection: Connection[fx.FoxgloveSession]) -> None:
        """Log the client count, send ``serverInfo`` and advertise the graph's topics and
        services."""
        self.log(f"Foxglove client connected.  {len(self.connections)} clients total.")
        with connection.lock:
            frames = connection.session.hello() + connection.session.update_graph(*self._graph)
        connection.send(frames)

    def receive(self, connection: Connection[fx.FoxgloveSession], data: str | bytes) -> None:
        """Feed the client's message to its session, send the replies, and carry out its events
        (subscribe, advertise, call...); a refusal reaches the client as an error status."""
        with connection.lock:
            reaction = connection.session.receive(data)
        if reaction.frames:
            connection.send(reaction.frames)
        for event in reaction.events:
            try:
                self._carry_out(connection, event)
            except Exception as exc:  # a refusal of the graph reaches the client as a status
                connection.send([connection.session.status(fx.ERROR, f"{exc}")])

    def closed(self, connection: Connection[fx.FoxgloveSession]) -> None:
        """Drop the client's subscriptions and client channels, then log the client count."""
        with connection.lock:
            topics = set(connection.session.subscriptions.values())
            published = set(connection.session.client_channels.values())
        for topic in topics:
            self._unsubscribe(connection, topic)
        for topic in published:
            self._unadvertise(connection, topic)
        self.log(f"Foxglove client disconnected. {len(self.connections)} clients total.")

    def render(
        self, session: fx.FoxgloveSession, message: tuple[str, bytes, int]
    ) -> list[fx.Frame | Pieces]:
        """The binary ``messageData`` frames of one ROS message for the session's subscriptions."""
        return session.deliver(*message)

    def oversized(self, session: fx.FoxgloveSession, reason: str) -> fx.Frame | None:
        """An error status naming the size limit, sent before the connection closes."""
        return session.status(
            fx.ERROR, f"Message refused ({reason}): the limit is {self.max_message} bytes"
        )

    def idle(self, session: fx.FoxgloveSession) -> bool:
        """Whether the client neither subscribes nor publishes (so it may be closed first)."""
        return not session.subscriptions and not session.client_channels

    def _follow_clock(self) -> None:
        """With ``/use_sim_time`` set, ``/clock`` becomes the clients' time (``time`` frames)."""
        self._sim_time = bool(self.node.params.get("/use_sim_time", False))
        if not self._sim_time:
            return
        from rosx.msg.codec.classes import get_message_class  # noqa: PLC0415 - sim time only

        def tick(clock: Any) -> None:
            stamp = clock.clock.secs * 1_000_000_000 + clock.clock.nsecs
            for connection in list(self.connections):
                connection.send([connection.session.time(stamp)])

        clock_class = get_message_class("rosgraph_msgs/Clock")
        self._clock = self.node.subscribe("/clock", clock_class, tick, queue_size=1)

    # -- the graph -----------------------------------------------------------------------------

    def _read_graph(self) -> tuple[dict[str, str], dict[str, str]]:
        master = self.node.master
        state = registrations(master, types=True)
        # Topics someone publishes or subscribes to: the master keeps the type of a topic
        # whose nodes are all gone, which is no channel. (foxglove_bridge offers published
        # topics only; a subscribed one, a turtle's cmd_vel, gives a client its schema to
        # publish with.)
        live = {*state.publishers, *state.subscribers}
        topics = {name: kind for name, kind in state.topic_types.items() if name in live}
        names = set(state.services)
        for name in names - set(self._service_types):
            with contextlib.suppress(Exception):  # a service that does not answer: not offered
                self._service_types[name] = self.node.probe_service(name, timeout=2.0).get(
                    "type", ""
                )
        for name in set(self._service_types) - names:
            del self._service_types[name]
        return topics, {n: t for n, t in self._service_types.items() if t}

    async def _poll(self) -> None:
        loop = asyncio.get_running_loop()
        while True:
            await asyncio.sleep(POLL_PERIOD)
            with contextlib.suppress(Exception):  # a master that is away for a moment
                self._graph = await loop.run_in_executor(self._pool, self._read_graph)
                for connection in list(self.connections):
                    with connection.lock:
                        frames = connection.session.update_graph(*self._graph)
                    if frames:
                        connection.send(frames)

    def _carry_out(self, connection: Connection[fx.FoxgloveSession], event: fx.Event) -> None:
        if isinstance(event, fx.Subscribe):
            self._subscribe(connection, event.topic)
        elif isinstance(event, fx.Unsubscribe):
            self._unsubscribe(connection, event.topic)
        elif isinstance(event, fx.Advertise):
            self._advertise(connection, event)
        elif isinstance(event, fx.Unadvertise):
            self._unadvertise(connection, event.topic)
        elif isinstance(event, fx.PublishRaw):
            entry = self._published.get(event.topic)
            if entry is not None:
                entry[0].publish_serialized(event.payload)
        elif isinstance(event, fx.CallService):
            self._call(connection, event)
        elif isinstance(event, fx.GetParameters):
            values = self._parameters(event.names)
            connection.send([connection.session.parameter_values(values, event.id)])
        elif isinstance(event, fx.SetParameters):
            for name, value in event.values:
                self.node.params.set(name, value)
            if event.id is not None:
                values = self._parameters(tuple(name for name, _ in event.values))
                connection.send([connection.session.parameter_values(values, event.id)])

    def _subscribe(self, connection: Connection[fx.FoxgloveSession], topic: str) -> None:
        with self._lock:
            entry = self._subscribed.get(topic)
            if entry is not None:
                entry[1].add(connection)
                return
            clients = {connection}
        subscriber = self.node.subscribe(
            topic, None, lambda raw: self._on_message(topic, clients, raw)
        )
        with self._lock:
            self._subscribed[topic] = (subscriber, clients)

    def _on_message(
        self, topic: str, clients: set[Connection[fx.FoxgloveSession]], raw: RawMessage
    ) -> None:
        message = (topic, raw._buff, time.time_ns())
        for connection in list(clients):
            connection.queue_message(topic, message, 100)

    def _unsubscribe(self, connection: Connection[fx.FoxgloveSession], topic: str) -> None:
        with self._lock:
            entry = self._subscribed.get(topic)
            if entry is None:
                return
            entry[1].discard(connection)
            if entry[1]:
                return
            del self._subscribed[topic]
        entry[0].unregister()

    def _advertise(self, connection: Connection[fx.FoxgloveSession], event: fx.Advertise) -> None:
        with self._lock:
            entry = self._published.get(event.topic)
            if entry is None:
                publisher = self.node.advertise(event.topic, event.msg_class, queue_size=100)
                entry = self._published[event.topic] = (publisher, set())
            entry[1].add(connection)

    def _unadvertise(self, connection: Connection[fx.FoxgloveSession], topic: str) -> None:
        with self._lock:
            entry = self._published.get(topic)
            if entry is None:
                return
            entry[1].discard(connection)
            if entry[1]:
                return
            del self._published[topic]
        entry[0].unregister()

    def _call(self, connection: Connection[fx.FoxgloveSession], call: fx.CallService) -> None:
        session = connection.session
        try:
            client = self.node.service_client(call.service, get_service_class(call.type))
            try:
                payload = client.call_serialized(call.payload, timeout=30.0)
            finally:
                client.close()
        except Exception as exc:  # whatever failed, the client gets its answer
            connection.send([session.call_failure(call, str(exc))])
        else:
            connection.send([session.call_response(call, payload)])

    def _parameters(self, names: tuple[str, ...]) -> dict[str, Any]:
        params = self.node.params
        wanted = names or tuple(params.names())
        values = {}
        for name in wanted:
            with contextlib.suppress(KeyError):
                values[name] = params.get(name)
        return values


__all__ = ["POLL_PERIOD", "FoxgloveServer"]
