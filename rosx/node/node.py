"""`Node`: a ROS 1 node with a synchronous facade, any number of them in one process.

A node owns a Slave API server (XML-RPC) and a TCPROS server, both on the process's event loop
(`rosx.transport.loop_thread.process_loop`), and registers its publications, subscriptions and
services with the master (ROS wiki ROS/Master_API, ROS/Slave_API). Like a rospy node it
publishes its log on ``/rosout`` and serves ``~get_loggers`` and ``~set_logger_level``.

Every public method may be called from any thread except the I/O loop's (user callbacks never
run there). Calls to the master are made on the caller's thread with the blocking XML-RPC
client; socket work happens on the loop. `shutdown` (also reached through the Slave API's
``shutdown`` and, when installed, SIGINT/SIGTERM) unregisters everything from the master, closes
every connection and runs the hooks given to `on_shutdown`. While it runs, the process's
master watch (`rosx.node.watchdog`) registers it again with a master that restarted.
"""

from __future__ import annotations

import contextlib
import os
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from typing import TYPE_CHECKING, Any, cast

from rosx.master.client import MasterClient, reply_value
from rosx.master.defaults import master_uri as find_master_uri
from rosx.names import make_global_ns, ns_join, resolve, resolve_remappings
from rosx.node import local, rosout, unixros
from rosx.node.clock import Clock
from rosx.node.errors import NodeShutdownError, ServiceError
from rosx.node.handles import Publisher, ServiceHandle, Subscriber
from rosx.node.log_services import RosoutPublisher, advertise_logger_services
from rosx.node.params import ParamCache, ParamClient
from rosx.node.publication import Publication
from rosx.node.service import ServiceServer
from rosx.node.service_client import ServiceClient, probe_service
from rosx.node.slave_api import SlaveApi
from rosx.node.startup import set_private_params
from rosx.node.subscription import RawMessage, Subscription
from rosx.node.tcpros_server import TcprosServer
from rosx.node.watchdog import master_watch
from rosx.signals import wait
from rosx.transport.aclient import AsyncXmlRpcClient
from rosx.transport.address import advertised_host, bind_host, foreign_address_warning
from rosx.transport.client import XmlRpcClient
from rosx.transport.loop_thread import process_loop
from rosx.transport.server import XmlRpcServer
from rosx.wire.header import Refused
from rosx.wire.rosrpc import accept_client, format_rosrpc_uri
from rosx.wire.tcpros import Publication as PublicationInfo
from rosx.wire.tcpros import accept_subscriber

if TYPE_CHECKING:
    import socket
    from collections.abc import Callable, Mapping

    from rosx.msg.codec.message import Message, ServiceDefinition
    from rosx.node.receiver import Entry
    from rosx.transport.loop_thread import LoopThread
    from rosx.wire.framing import FrameReader

#: A node's worker threads: they run its service handlers and hand a latched message to a
#: callback added after the message came. They start only when calls overlap and are shared by
#: all the node's services. The bound is how many calls the node serves at once; more wait in
#: line. One is too few: as in rospy (a thread per call) a handler may block, on I/O, a sleep or
#: a call to another service of the same node, which would then wait for itself. Many are
#: useless: Python handlers hold the GIL, so past a few threads only waiting handlers gain, and
#: a process hosting many nodes (``rosx sim``, the tests) would keep each node's idle threads.
#: 8 serves a few slow callers and a nested call or two at once; a ninth call waits its turn.
WORKERS = 8
#: How long a shutting-down node waits for the master to take its unregistrations (one round
#: trip). A master that is gone refuses at once; a loaded one may take seconds, and a node that
#: gave up early would stay listed after it left (rospy waits as long as it takes).
_UNREGISTER_TIMEOUT = 10.0
#: How long a second `Node.shutdown` caller waits for the first to finish.
_FINISH_TIMEOUT = 15.0


class Node:
    """A ROS 1 node; see the module docstring. Create it, `start` it, use it, `shutdown`."""

    def __init__(
        self,
        name: str,
        *,
        namespace: str | None = None,
        master_uri: str | None = None,
        remappings: Mapping[str, str] | None = None,
        host: str | None = None,
        environ: Mapping[str, str] | None = None,
        xmlrpc_port: int = 0,
        tcpros_port: int = 0,
        rosout_enabled: bool = True,
        log_level: int = rosout.INFO,
        console: Callable[[int, str], None] | None = None,
        io: LoopThread | None = None,
        private_params: Mapping[str, str] | None = None,
        warn_refusals: bool = False,
        first_seq: int = 1,
    ) -> None:
        env = os.environ if environ is None else environ
        self.environ = env
        self.namespace = make_global_ns(namespace or env.get("ROS_NAMESPACE") or "/")
        self.name = name if name.startswith("/") else ns_join(self.namespace, name)
        self.master_uri = find_master_uri(env, master_uri)
        self.remappings = resolve_remappings(
            remappings or {}, self.namespace, self.name, strict=False
        )
        self._host_remap = host
        self.host = advertised_host(env, host)
        self._bind = bind_host(env, host)
        self._ports = (xmlrpc_port, tcpros_port)
        self.io = io or process_loop()
        self.uri = ""
        self.client = XmlRpcClient()
        self.master = MasterClient(self.master_uri, self.name, self.client)
        self.param_cache = ParamCache()
        self.params = ParamClient(self.master, self.resolve, lambda: self.uri, self.param_cache)
        self.publications: dict[str, Publication] = {}
        self.subscriptions: dict[str, Subscription] = {}
        self.services: dict[str, ServiceServer] = {}
        self._pub_handles: dict[str, int] = {}
        #: The ``header.seq`` of each publication's first message (1: rospy's count; 0: roscpp's).
        self.first_seq = first_seq
        self._lock = threading.RLock()
        self._shutdown = threading.Event()
        self._closed = threading.Event()
        self._closer: int | None = None
        self._hooks: list[Callable[[str], object]] = []
        self._aclient: AsyncXmlRpcClient | None = None
        self._xmlrpc: XmlRpcServer | None = None
        self._tcpros = TcprosServer(self.io, self._on_connection)
        self._workers = ThreadPoolExecutor(WORKERS, thread_name_prefix=f"rosx-worker{self.name}")
        self._rosout_enabled = rosout_enabled
        self.log_sink = rosout.NodeLog(self.name, level=log_level, console=console, environ=env)
        self.shutdown_reason = ""
        #: ``_name:=value`` arguments (name without ``_`` → YAML text), set as ``~name`` on start.
        self.private_params = dict(private_params or {})
        #: Whether a refused subscriber or service client is logged as a warning: rospy's nodes
        #: warn (a subscriber of another type, say), roscpp's say nothing.
        self.warn_refusals = warn_refusals
        #: The node's ROS time: the wall clock, or ``/clock`` (`rosx.node.simtime`).
        self.clock = Clock()

    # -- lifecycle ---------------------------------------------------------------------------

    def start(self) -> Node:
        """Set the private parameters, start the servers, advertise ``/rosout`` and the logger
        services; returns self.

        Raises:
            MasterUnreachable: the master cannot be reached.
            MasterError: the master refused a registration.
            ParamArgsError: a private parameter's value cannot be set.
        """
        try:
            self._start()
        except BaseException:
            self.shutdown("start-up failed")
            raise
        return self

    def _start(self) -> None:
        warning = foreign_address_warning(self.environ, self._host_remap)
        if warning is not None:
            self.log_sink.log(rosout.WARN, warning)
        if self.private_params:
            set_private_params(
                self.master,
                self.private_params,
                node_name=self.name,
                namespace=self.namespace,
                remappings=self.remappings,
            )
        self.io.run(self._start_servers())
        if self._rosout_enabled:
            self.log_sink.publish = RosoutPublisher(self)
        advertise_logger_services(self)
        master_watch(self.io).add(self)

    async def _start_servers(self) -> None:
        self._aclient = AsyncXmlRpcClient()
        server = XmlRpcServer(
            SlaveApi(self).methods(),
            host=self._bind,
            port=self._ports[0],
            advertised_host=self.host,
        )
        await server.start()
        self._xmlrpc = server
        self.uri = server.uri
        self._tcpros.start(self._bind, self._ports[1])
        if unixros.ENABLED:
            with contextlib.suppress(OSError):  # TCPROS alone, then
                self._tcpros.start_unix(unixros.new_address())
        local.register(self.uri, self.name, self.publications.get)

    def is_shutdown(self) -> bool:
        """Whether the node has been shut down."""
        return self._shutdown.is_set()

    @property
    def shutdown_event(self) -> threading.Event:
        """Set when the node shuts down (for sleeping until then)."""
        return self._shutdown

    def on_shutdown(self, hook: Callable[[str], object]) -> None:
        """Call ``hook(reason)`` when the node shuts down (at once if it already has)."""
        if self._shutdown.is_set():
            hook(self.shutdown_reason)
        else:
            self._hooks.append(hook)

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        """Block until the node shuts down; False if ``timeout`` passed first."""
        return wait(self._shutdown, timeout)

    def shutdown(self, reason: str = "") -> None:
        """Unregister everything from the master, close every connection, run the hooks.

        A second caller (a ``rosnode kill`` shuts down on a thread of its own) waits until the
        shutdown in progress is complete, so a process never exits still registered.
        """
        with self._lock:
            closer = self._closer
            if closer is None:
                self._closer = threading.get_ident()
                self.shutdown_reason = reason
                self._shutdown.set()
                self.clock.wake()
        if closer is not None:
            if closer != threading.get_ident() and not self.io.in_loop_thread():
                self._closed.wait(_FINISH_TIMEOUT)
            return
        master_watch(self.io).remove(self)
        try:
            for hook in self._hooks:
                try:
                    hook(reason)
                except Exception as exc:  # every hook runs
                    print(f"error in shutdown hook: {exc}", file=sys.stderr)
            self._unregister_all()
            if self.io.in_loop_thread():
                self.io.spawn(self._close_all())
            else:
                self.io.run(self._close_all(), timeout=10.0)
            self._workers.shutdown(wait=False, cancel_futures=True)
            self.client.close()
        finally:
            self._closed.set()

    def _unregister_all(self) -> None:
        calls: list[tuple[str, tuple[object, ...]]] = []
        calls += [("unregisterPublisher", (t, self.uri)) for t in self.publications]
        calls += [("unregisterSubscriber", (t, self.uri)) for t in self.subscriptions]
        calls += [("unregisterService", (n, s.uri)) for n, s in self.services.items()]
        # in one round trip, as rospy unregisters; a gone master must not stop the shutdown
        with contextlib.suppress(Exception):
            self.master.multicall(calls, timeout=_UNREGISTER_TIMEOUT)
        self.params.unsubscribe_all()

    async def _close_all(self) -> None:
        local.unregister(self.uri)
        self._tcpros.close()
        for pub in list(self.publications.values()):
            pub.close()
        for sub in list(self.subscriptions.values()):
            sub.close()
        for srv in list(self.services.values()):
            srv.close()
        if self._xmlrpc is not None:
            await self._xmlrpc.close()
        if self._aclient is not None:
            await self._aclient.close()

    def request_shutdown(self, reason: str) -> None:
        """Shut down on a thread of its own (for the Slave API, which runs on the loop).

        The Slave API stops taking connections at once, as rospy's has closed by the time it
        answers ``shutdown``: a ``rosnode ping`` right after ``rosnode kill`` finds no node.
        """
        if self._xmlrpc is not None:
            self._xmlrpc.stop_listening()
        threading.Thread(target=self.shutdown, args=(reason,), daemon=True).start()

    def _check_alive(self) -> None:
        if self._shutdown.is_set():
            raise NodeShutdownError(f"node [{self.name}] has been shut down")

    # -- names -------------------------------------------------------------------------------

    def resolve(self, name: str) -> str:
        """``name`` resolved in this node's namespace (``~x`` privately), then remapped."""
        return resolve(name, self.namespace, self.name, self.remappings, strict=False)

    def tcpros_address(self) -> tuple[str, int]:
        """The host and port of this node's TCPROS server, as advertised."""
        return self.host, self._tcpros.port

    def unixros_address(self) -> str | None:
        """The Unix socket this node's publications accept subscribers on (`rosx.node.unixros`)."""
        return self._tcpros.unix_address

    # -- publishing --------------------------------------------------------------------------

    def advertise(
        self,
        topic: str,
        data_class: type[Message],
        *,
        queue_size: int | None = None,
        latch: bool = False,
        headers: Mapping[str, str] | None = None,
    ) -> Publisher:
        """Publish ``topic`` with messages of ``data_class`` (registered with the master).

        ``queue_size``: per subscriber, drop-oldest; ``0`` unbounded; ``None`` blocks the
        publishing thread while a subscriber is far behind, as rospy's synchronous publishing.
        ``headers``: fields added to the connection header subscribers get from now on.
        """
        info = PublicationInfo(
            self.resolve(topic), data_class._type, data_class._md5sum, data_class._full_text, latch
        )
        publication = self._publication(info, queue_size, data_class._has_header)
        if headers:
            publication.add_headers(headers)
        return Publisher(
            self, publication, data_class, lambda: self._release_publication(publication)
        )

    def advertise_raw(
        self,
        topic: str,
        msg_type: str,
        md5sum: str,
        message_definition: str,
        *,
        queue_size: int | None = None,
        latch: bool = False,
    ) -> Publisher:
        """Publish ``topic`` with messages already serialized (`Publisher.publish_serialized`),
        announced with the given type, md5sum and definition (what ``rosbag play`` replays)."""
        info = PublicationInfo(self.resolve(topic), msg_type, md5sum, message_definition, latch)
        raw = cast("type[Message]", RawMessage)  # publishes RawMessage objects as they are
        publication = self._publication(info, queue_size, False)
        return Publisher(self, publication, raw, lambda: self._release_publication(publication))

    def _publication(
        self, info: PublicationInfo, queue_size: int | None, has_header: bool
    ) -> Publication:
        self._check_alive()
        name = info.topic
        with self._lock:
            publication = self.publications.get(name)
            new = publication is None
            if publication is None:
                publication = Publication(
                    self.io,
                    PublicationInfo(name, info.type, info.md5sum, info.message_definition, False),
                    queue_size=queue_size,
                    has_header=has_header,
                    first_seq=self.first_seq,
                )
                publication.unix_address = self._tcpros.unix_address
                self.publications[name] = publication
            elif publication.info.type != info.type:
                raise ValueError(
                    f"topic [{name}] is already published with type [{publication.info.type}], "
                    f"not [{info.type}]"
                )
            publication.set_latching(info.latching)
            self._pub_handles[name] = self._pub_handles.get(name, 0) + 1
        if new:
            self.master.call("registerPublisher", name, info.type, self.uri)
            if self._shutdown.is_set():  # shut down meanwhile: do not leave it registered
                self._call_quietly("unregisterPublisher", name, self.uri)
        return publication

    def _release_publication(self, publication: Publication) -> None:
        name = publication.topic
        with self._lock:
            count = self._pub_handles.get(name, 0) - 1
            if count > 0:
                self._pub_handles[name] = count
                return
            self._pub_handles.pop(name, None)
            if self.publications.get(name) is not publication:
                return
            del self.publications[name]
        if not self._shutdown.is_set():
            self._call_quietly("unregisterPublisher", name, self.uri)
        self.io.call_soon(publication.close)

    # -- subscribing -------------------------------------------------------------------------

    def subscribe(
        self,
        topic: str,
        data_class: type[Message] | None,
        callback: Callable[[Any], object],
        *,
        queue_size: int | None = None,
        tcp_nodelay: bool = False,
    ) -> Subscriber:
        """Call ``callback`` with each message of ``topic``, on the topic's receiver thread.

        ``data_class=None`` subscribes to any type (rospy's ``AnyMsg``): the callback gets
        `RawMessage` objects. ``queue_size`` bounds the topic's queue (drop-oldest); the first
        subscriber of a topic in the node sets it, as in rospy.
        """
        self._check_alive()
        name = self.resolve(topic)
        with self._lock:
            subscription = self.subscriptions.get(name)
            new = subscription is None
            if subscription is None:
                subscription = Subscription(
                    io=self.io,
                    topic=name,
                    msg_class=data_class,
                    caller_id=self.name,
                    workers=self._workers,
                    xmlrpc=self._call_peer,
                    queue_size=queue_size,
                    tcp_nodelay=tcp_nodelay,
                    on_error=self._log_error,
                )
                self.subscriptions[name] = subscription
        entry = subscription.add(callback, Subscription.decoder(data_class))
        handle = Subscriber(
            self,
            subscription,
            entry,
            data_class,
            lambda: self._release_subscriber(subscription, entry),
        )
        if new:
            mark = subscription.updates
            uris = self.master.call("registerSubscriber", name, subscription.type, self.uri)
            if self._shutdown.is_set():  # shut down meanwhile: do not leave it registered
                self._call_quietly("unregisterSubscriber", name, self.uri)
                return handle
            self.io.call_soon(self._apply_registration, subscription, list(uris), mark)
        return handle

    def _apply_registration(self, subscription: Subscription, uris: list[str], mark: int) -> None:
        subscription.set_publishers(uris, additive=subscription.updates != mark)

    def publisher_update(self, topic: str, uris: list[str]) -> None:
        """Apply a ``publisherUpdate`` (on the loop)."""
        subscription = self.subscriptions.get(topic)
        if subscription is not None:
            subscription.updates += 1
            subscription.set_publishers(uris, additive=time.monotonic() < subscription.keep_until)

    async def _call_peer(self, uri: str, method: str, *params: object) -> Any:
        assert self._aclient is not None
        return reply_value(await self._aclient.call(uri, method, *params))

    def _release_subscriber(self, subscription: Subscription, entry: Entry) -> None:
        subscription.remove(entry)
        with self._lock:
            if subscription.callback_count or (
                self.subscriptions.get(subscription.topic) is not subscription
            ):
                return
            del self.subscriptions[subscription.topic]
        if not self._shutdown.is_set():
            self._call_quietly("unregisterSubscriber", subscription.topic, self.uri)
        self.io.call_soon(subscription.close)

    # -- services ----------------------------------------------------------------------------

    def advertise_service(
        self,
        name: str,
        service_class: type[ServiceDefinition],
        handler: Callable[[Any], object],
        *,
        server_class: type[ServiceServer] = ServiceServer,
        on_exception: Callable[[Exception], object] | None = None,
    ) -> ServiceHandle:
        """Serve ``name``: ``handler(request)`` runs on a pool thread for each call.

        ``server_class`` decides how failures are answered (rospy's way by default);
        ``on_exception`` gets what a handler raises (other than `ServiceError`) instead of the
        node's error log.
        """
        self._check_alive()
        resolved = self.resolve(name)
        with self._lock:
            if resolved in self.services:
                raise ServiceError(f"service [{resolved}] already registered")
            server = server_class(
                io=self.io,
                name=resolved,
                service_class=service_class,
                handler=handler,
                executor=self._workers,
                on_error=self._log_error,
                on_exception=on_exception,
            )
            server.uri = format_rosrpc_uri(self.host, self._tcpros.port)
            self.services[resolved] = server
        self.master.call("registerService", resolved, server.uri, self.uri)
        if self._shutdown.is_set():  # shut down meanwhile: do not leave it registered
            self._call_quietly("unregisterService", resolved, server.uri)
        return ServiceHandle(self, server, lambda: self._release_service(server))

    def _release_service(self, server: ServiceServer) -> None:
        with self._lock:
            if self.services.get(server.name) is not server:
                return
            del self.services[server.name]
        if not self._shutdown.is_set():
            self._call_quietly("unregisterService", server.name, server.uri)
        self.io.call_soon(server.close)

    def service_client(
        self, name: str, service_class: type[ServiceDefinition], *, persistent: bool = False
    ) -> ServiceClient:
        """A client of service ``name`` (resolved in this node's namespace)."""
        return ServiceClient(self.master, self.resolve(name), service_class, persistent=persistent)

    def probe_service(self, name: str, *, timeout: float | None = None) -> dict[str, str]:
        """The header the server of ``name`` sends to a probe (it names the service's type)."""
        return probe_service(self.master, self.resolve(name), timeout=timeout)

    # -- the TCPROS server's dispatch (on the loop) ------------------------------------------

    async def _on_connection(
        self, kind: str, sock: socket.socket, header: dict[str, str], reader: FrameReader
    ) -> str | None:
        if self._shutdown.is_set():
            return "Node is shutting down"
        if kind == "topic":
            infos = {name: pub.info for name, pub in self.publications.items()}
            verdict = accept_subscriber(header, callerid=self.name, publications=infos)
            if isinstance(verdict, Refused):
                return self._refused(verdict.reason, header)
            self.publications[verdict.publication.topic].accept(sock, verdict)
            return None
        services = {name: srv.info for name, srv in self.services.items()}
        answer = accept_client(header, callerid=self.name, services=services)
        if isinstance(answer, Refused):
            return self._refused(answer.reason, header)
        await self.services[answer.service.service].serve(sock, answer, header, reader)
        return None

    def _refused(self, reason: str, header: dict[str, str]) -> str:
        """``reason`` for the refused peer, said as rospy's warning says it (`warn_refusals`)."""
        if self.warn_refusals:
            self.log(rosout.WARN, f"Could not process inbound connection: {reason}{header}")
        return reason

    # -- logging -----------------------------------------------------------------------------

    def log(
        self, level: int, message: str, *, file: str = "", function: str = "", line: int = 0
    ) -> None:
        """Log ``message`` at ``level`` (`rosx.node.rosout` DEBUG…FATAL) to /rosout and console."""
        self.log_sink.log(level, message, file=file, function=function, line=line)

    def _log_error(self, message: str) -> None:
        self.log_sink.log(rosout.ERROR, message)

    def _call_quietly(self, method: str, *params: object) -> None:
        try:
            self.master.call(method, *params, timeout=_UNREGISTER_TIMEOUT)
        except Exception as exc:  # unregistering is best effort
            self._log_error(f"{method} failed: {exc}")

    def __enter__(self) -> Node:
        return self.start() if not self.uri else self

    def __exit__(self, *exc: object) -> None:
        self.shutdown("context exited")
