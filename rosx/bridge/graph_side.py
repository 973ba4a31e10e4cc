"""The bridge's side of the ROS graph: one node whose topics and services serve every client.

`GraphSide` carries out the events of the clients' sessions (`rosx.bridge.ops`) through the
node runtime's public API: one publisher per topic however many clients advertise it (what
it publishes in its first second also reaches the subscribers still connecting, `early`), one
subscription per topic however many clients subscribe (taking messages as their serialized
bytes, so a cbor-raw client costs no decoding and a topic needs no known type), one service
per service a client advertises. A topic's message is encoded once per encoding and its
message goes to each subscribed client's queue (`Client.queue_message`) on the receiving
thread, and is encoded when the client's writer takes it: a message dropped for a slow client
costs no encoding, and each encoding is made once for every client that sends it.

Clients are anything with the `Client` protocol: the WebSocket server's connections, or a
test's recorder.
"""

from __future__ import annotations

import threading
import time
from concurrent.futures import Future, ThreadPoolExecutor
from typing import TYPE_CHECKING, Any, Protocol

from rosx.bridge import ops
from rosx.bridge.convert import ConversionError
from rosx.bridge.early import EarlyMessages
from rosx.bridge.outgoing import Outgoing
from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import ServiceError
from rosx.node.clock import now

if TYPE_CHECKING:
    from collections.abc import Callable, Sequence

    from rosx.bridge.protocol import Session
    from rosx.msg.codec.message import Message
    from rosx.node import Node, Publisher, ServiceHandle, Subscriber
    from rosx.node.subscription import RawMessage

#: Calls of services the clients make at once; more wait their turn.
CALL_WORKERS = 16
#: How long a graph caller of a client's service waits for the client's answer (seconds).
SERVICE_TIMEOUT = 30.0


class Client(Protocol):
    """A connected client as `GraphSide` sees it."""

    session: Session
    lock: threading.Lock

    def send(self, frames: list[ops.Frame]) -> None:
        """Queue control frames (statuses, service frames) for the client; any thread."""

    def queue_message(self, topic: str, message: Outgoing, bound: int) -> bool:
        """Queue a message of ``topic`` (rendered into frames by the session when sent),
        keeping at most ``bound`` of the topic waiting; True if the oldest was dropped for
        it. Any thread."""

    def close(self, code: int, reason: str) -> None:
        """Close the connection; any thread."""


class _Advertised:
    __slots__ = ("clients", "early", "publisher")

    def __init__(self, publisher: Publisher) -> None:
        self.publisher = publisher
        self.clients: set[Client] = set()
        self.early = EarlyMessages()
        publisher.add_watcher(self.early)


class _Subscribed:
    __slots__ = ("classes", "clients", "readers", "subscriber")

    def __init__(self) -> None:
        self.subscriber: Subscriber | None = None
        self.clients: set[Client] = set()
        #: ``clients`` as the receiving thread reads them (replaced, never changed).
        self.readers: tuple[Client, ...] = ()
        self.classes: dict[str, type[Message] | None] = {}


class _Served:
    """A service a client serves: the graph's calls wait for the client's answers."""

    __slots__ = ("client", "handle", "waiting")

    def __init__(self, client: Client) -> None:
        self.client = client
        self.handle: ServiceHandle | None = None
        self.waiting: dict[str, Future[Message]] = {}


class GraphSide:
    """The graph as the clients reach it, through ``node`` (started, owned by the caller)."""

    def __init__(
        self,
        node: Node,
        *,
        default_queue: int = 100,
        log: Callable[[str], object] | None = None,
    ) -> None:
        self.node = node
        self.default_queue = default_queue
        #: Where what a client was refused is logged (the bridge's terminal).
        self.log = log
        self._lock = threading.Lock()
        self._advertised: dict[str, _Advertised] = {}
        self._subscribed: dict[str, _Subscribed] = {}
        self._served: dict[str, _Served] = {}
        self._calls = ThreadPoolExecutor(CALL_WORKERS, thread_name_prefix="rosx-bridge-call")

    # -- input from a client ------------------------------------------------------------------

    def receive(self, client: Client, data: str | bytes) -> None:
        """Handle one frame of ``client`` (on any thread but the I/O loop's)."""
        with client.lock:
            reaction = client.session.receive(data, now())
        self.react(client, reaction)

    def react(self, client: Client, reaction: ops.Reaction) -> None:
        """Send a reaction's frames, log its errors and carry out its events."""
        if reaction.frames:
            client.send(reaction.frames)
        if reaction.errors and self.log is not None:
            for text in reaction.errors:
                self.log(f"[Client {client.session.client}] {text}")
        for event in reaction.events:
            try:
                self._carry_out(client, event)
            except Exception as exc:  # a refusal of the graph reaches the client as a status
                self._tell(client, client.session.error(f"{_op(event)}: {exc}"))

    def _tell(self, client: Client, reaction: ops.Reaction) -> None:
        if reaction.frames or reaction.events:
            self.react(client, reaction)

    def _carry_out(self, client: Client, event: ops.Event) -> None:
        if isinstance(event, ops.Publish):
            entry = self._advertised.get(event.topic)
            if entry is None:  # the advertisement was refused (another client's type)
                raise ValueError(f"{event.topic} is not advertised by this client")
            entry.early.keep(event.message)
            entry.publisher.publish(event.message)
        elif isinstance(event, ops.Subscribe):
            self._subscribe(client, event)
        elif isinstance(event, ops.Unsubscribe):
            self._unsubscribe(client, event.topic)
        elif isinstance(event, ops.Advertise):
            self._advertise(client, event)
        elif isinstance(event, ops.Unadvertise):
            self._unadvertise(client, event.topic)
        elif isinstance(event, ops.PublishUntyped):
            self._calls.submit(self._publish_untyped, client, event)
        elif isinstance(event, ops.CallService):
            self._calls.submit(self._call_service, client, event)
        elif isinstance(event, ops.AdvertiseService):
            self._advertise_service(client, event)
        elif isinstance(event, ops.UnadvertiseService):
            self._unadvertise_service(client, event.service)
        elif isinstance(event, ops.ServiceReply):
            self._service_reply(event)
        elif isinstance(event, ops.Close):
            client.close(event.code, event.reason)

    def disconnect(self, client: Client) -> None:
        """Undo everything ``client`` set up (it has gone)."""
        with client.lock:
            session = client.session
            topics = list(session.topics)
            advertised = list(session.advertised)
            services = list(session.services)
        for topic in topics:
            self._unsubscribe(client, topic)
        for topic in advertised:
            self._unadvertise(client, topic)
        for service in services:
            self._unadvertise_service(client, service)

    def close(self) -> None:
        """Stop the service callers (the node is the caller's to shut down)."""
        for served in list(self._served.values()):
            for future in served.waiting.values():
                future.cancel()
        self._calls.shutdown(wait=False, cancel_futures=True)

    # -- topics --------------------------------------------------------------------------------

    def _advertise(self, client: Client, event: ops.Advertise) -> None:
        with self._lock:
            entry = self._advertised.get(event.topic)
            if entry is None:
                publisher = self.node.advertise(
                    event.topic, event.msg_class, queue_size=event.queue_size or None,
                    latch=event.latch,
                )  # fmt: skip
                entry = self._advertised[event.topic] = _Advertised(publisher)
            elif entry.publisher.type != event.msg_class._type:
                with client.lock:
                    client.session.advertised.pop(event.topic, None)
                raise ValueError(
                    f"{event.topic} is already advertised with type {entry.publisher.type}"
                )
            entry.clients.add(client)

    def _unadvertise(self, client: Client, topic: str) -> None:
        with self._lock:
            entry = self._advertised.get(topic)
            if entry is None:
                return
            entry.clients.discard(client)
            if entry.clients:
                return
            del self._advertised[topic]
        entry.publisher.unregister()

    def _publish_untyped(self, client: Client, event: ops.PublishUntyped) -> None:
        type_name = self.node.master.topic_types().get(self.node.resolve(event.topic))
        with client.lock:
            reaction = client.session.publish_typed(
                event.topic, type_name, event.values, event.id, now()
            )
        self.react(client, reaction)

    def _subscribe(self, client: Client, event: ops.Subscribe) -> None:
        with self._lock:
            entry = self._subscribed.get(event.topic)
            new = entry is None
            if entry is None:
                entry = self._subscribed[event.topic] = _Subscribed()
            entry.clients.add(client)
            entry.readers = tuple(entry.clients)
        if new:
            topic = event.topic
            assert entry is not None
            entry.subscriber = self.node.subscribe(
                topic, None, lambda raw: self._on_message(topic, entry, raw)
            )

    def _unsubscribe(self, client: Client, topic: str) -> None:
        with self._lock:
            entry = self._subscribed.get(topic)
            if entry is None:
                return
            entry.clients.discard(client)
            entry.readers = tuple(entry.clients)
            if entry.clients:
                return
            del self._subscribed[topic]
        if entry.subscriber is not None:
            entry.subscriber.unregister()

    def _on_message(self, topic: str, entry: _Subscribed, raw: RawMessage) -> None:
        type_name = raw.type
        msg_class = entry.classes.get(type_name, Ellipsis)
        if msg_class is Ellipsis:
            try:
                msg_class = get_message_class(type_name)
            except Exception:  # a type only the publisher knows: cbor-raw still serves
                msg_class = None
            entry.classes[type_name] = msg_class
        out = Outgoing(topic, raw._buff, msg_class, time.time_ns())
        self.fan_out(out, entry.readers)

    def fan_out(self, out: Outgoing, clients: Sequence[Client]) -> None:
        """Hand ``out`` to each of ``clients`` subscribed to its topic.

        When a client's queue overflows, its writer (on the I/O loop) is behind the topic:
        the receiving thread then lets the loop have the interpreter for a moment, which a
        thread taking messages as fast as a publisher floods them would otherwise hold.
        """
        behind = False
        for client in clients:
            options = client.session.options(out.topic)
            if options is not None:
                bound = options.queue_length or self.default_queue
                behind = client.queue_message(out.topic, out, bound) or behind
        if behind:
            time.sleep(0)

    # -- services the clients call ---------------------------------------------------------------

    def _call_service(self, client: Client, call: ops.CallService) -> None:
        try:
            header = self.node.probe_service(call.service, timeout=5.0)
            service_class = get_service_class(header.get("type", ""))
            with client.lock:
                request = client.session.service_request_message(call, service_class, now())
            response = self.node.service_client(call.service, service_class).call(request)
        except (ConversionError, ServiceError) as exc:
            failed = client.session.service_failed(call, str(exc))
        except Exception as exc:  # whatever failed, the client gets its answer
            failed = client.session.service_failed(call, f"{type(exc).__name__}: {exc}")
        else:
            client.send(client.session.service_done(call, response))
            return
        self.react(client, failed)

    # -- services the clients serve --------------------------------------------------------------

    def _advertise_service(self, client: Client, event: ops.AdvertiseService) -> None:
        served = _Served(client)
        with self._lock:
            previous = self._served.get(event.service)
            self._served[event.service] = served
        if previous is not None and previous.handle is not None:
            previous.handle.shutdown()
        served.handle = self.node.advertise_service(
            event.service,
            event.service_class,
            lambda request: self._serve(event.service, served, request),
        )

    def _serve(self, service: str, served: _Served, request: Message) -> Message:
        client = served.client
        with client.lock:
            request_id, frames = client.session.service_request(service, request)
        future: Future[Message] = Future()
        served.waiting[request_id] = future
        client.send(frames)
        try:
            return future.result(SERVICE_TIMEOUT)
        except TimeoutError:
            raise ServiceError(
                f"service [{service}]: the bridge's client did not answer in {SERVICE_TIMEOUT:g} s"
            ) from None
        finally:
            served.waiting.pop(request_id, None)

    def _service_reply(self, event: ops.ServiceReply) -> None:
        for served in list(self._served.values()):
            future = served.waiting.get(event.request_id)
            if future is None:
                continue
            if event.response is not None:
                future.set_result(event.response)
            else:
                future.set_exception(ServiceError(event.error or "service call failed"))
            return

    def _unadvertise_service(self, client: Client, service: str) -> None:
        with self._lock:
            served = self._served.get(service)
            if served is None or served.client is not client:
                return
            del self._served[service]
        for future in served.waiting.values():
            future.set_exception(ServiceError(f"service [{service}] was unadvertised"))
        if served.handle is not None:
            served.handle.shutdown()


def _op(event: Any) -> str:
    names = {
        ops.Advertise: "advertise",
        ops.Publish: "publish",
        ops.Subscribe: "subscribe",
        ops.AdvertiseService: "advertise_service",
    }
    return names.get(type(event), type(event).__name__.lower())


__all__ = ["CALL_WORKERS", "SERVICE_TIMEOUT", "Client", "GraphSide"]
