"""An asyncio XML-RPC server over HTTP/1.1 (the XML-RPC specification; ROS wiki ROS/Master_API
and ROS/Slave_API ride on it).

`XmlRpcServer` listens on a host and port (port 0 picks a free one), keeps connections alive
between calls, serves any number of connections at once, and hands each ``methodCall`` to a
handler: a callable taking the call's parameters, looked up by method name in a mapping (or
among an object's public methods). A handler returns the value to send, or an awaitable of it;
sync handlers run on the event loop, so they must not block. A handler raises `FaultError` to
answer with a chosen fault; any other exception becomes fault 1, worded as Python's
SimpleXMLRPCServer (ROS 1's server) words it, and the server carries on.

Bad requests are refused without harming anyone else: malformed HTTP gets an HTTP error and the
connection is closed; a method other than POST gets 501; a body that is not a ``methodCall``, or
an unknown method, gets an XML-RPC fault on a connection that stays open.

A handler may return `EncodedResponse` to send a ``methodResponse`` body it encoded (and may
have cached) itself.

A connection that sends nothing for `IDLE_TIMEOUT` seconds while no call of its own is being
answered is closed (neither rosmaster nor ROS 1's nodes ever close one, so a master there dies
of 1 024 forgotten connections). Clients lose nothing: rosx's clients, Python's
``xmlrpc.client`` (rospy, the ROS 1 tools) and roscpp's XmlRpc++ all reopen a kept-alive
connection the server closed and send the call again. When the process runs short of file
descriptors, the oldest idle connections are closed at once (`rosx.transport.descriptors`), so
a master holding a thousand forgotten connections still answers the next call.
"""

from __future__ import annotations

import asyncio
import inspect
import logging
import socket
from collections.abc import Mapping

from rosx.transport import descriptors
from rosx.transport.address import http_uri
from rosx.transport.errors import FaultError
from rosx.wire.errors import HttpError, ProtocolError, UnencodableError
from rosx.wire.xmlrpc import decode_call, encode_fault, encode_response
from rosx.wire.xmlrpc_http import (
    DEFAULT_MAX_BODY_SIZE,
    RequestReader,
    build_error_response,
    build_response,
)

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable, Iterator
    from typing import Any, TypeAlias

    Handler: TypeAlias = Callable[..., Any]

_log = logging.getLogger(__name__)
_READ_SIZE = 1 << 16

#: Seconds a connection may stay silent between calls before the server closes it. Longer than
#: any pause inside a working client's burst of calls (a tool's, a launch's registrations, a
#: node's once-a-second master watch), so busy connections are never cut; short enough that
#: the file descriptors of connections abandoned by hung or careless clients come back within
#: half a minute. Reopening one costs a client a loopback handshake, well under a millisecond.
IDLE_TIMEOUT = 30.0


class EncodedResponse:
    """A handler's result already encoded: `body` is the ``methodResponse`` document for `value`.

    `value` is still needed for ``system.multicall``, which nests results in its own reply.
    """

    __slots__ = ("body", "value")

    def __init__(self, value: object, body: bytes) -> None:
        self.value = value
        self.body = body

    @classmethod
    def of(cls, value: object) -> EncodedResponse:
        """Encode `value` once, for replies served many times unchanged."""
        return cls(value, encode_response(value))


def public_methods(handler: object) -> dict[str, Handler]:
    """An object's public callables by name: how an object handler is exposed."""
    methods: dict[str, Handler] = {}
    for name in dir(handler):
        if not name.startswith("_"):
            attribute = getattr(handler, name)
            if callable(attribute):
                methods[name] = attribute
    return methods


def _python_fault(exc: BaseException) -> tuple[int, str]:
    # SimpleXMLRPCServer's wording, which ROS 1's tools show to users: "<class 'X'>:message".
    return 1, f"{type(exc)}:{exc}"


class XmlRpcServer:
    """Serves XML-RPC calls to handlers; `start` it in a running event loop, then `close` it.

    Args:
        handlers: Method name to handler, or an object whose public methods are the handlers.
        host: The address to listen on (127.0.0.1 unless told otherwise).
        port: The port; 0 picks a free one (see `port` once started).
        advertised_host: The host written in `uri`; `host` if not given.
        multicall: Also serve ``system.multicall``, as rosmaster does (roslaunch uses it).
        max_body_size: Largest request body accepted (413 beyond it).
        idle_timeout: Seconds of silence after which a connection is closed (`IDLE_TIMEOUT`
            unless given).
    """

    def __init__(
        self,
        handlers: Mapping[str, Handler] | object,
        *,
        host: str = "127.0.0.1",
        port: int = 0,
        advertised_host: str | None = None,
        multicall: bool = False,
        max_body_size: int = DEFAULT_MAX_BODY_SIZE,
        idle_timeout: float | None = None,
    ) -> None:
        if isinstance(handlers, Mapping):
            self._methods: dict[str, Handler] = dict(handlers)
        else:
            self._methods = public_methods(handlers)
        if multicall:
            self._methods["system.multicall"] = self._multicall
        self.host = host
        self.advertised_host = advertised_host or host
        self._requested_port = port
        self._max_body_size = max_body_size
        self._listener: descriptors.Listener | None = None
        # Each connection's task and when it last received bytes (None while a call of its
        # own is being answered, which no timeout cuts short).
        self._connections: dict[asyncio.Task[None], float | None] = {}
        self.idle_timeout = IDLE_TIMEOUT if idle_timeout is None else idle_timeout
        self._sweeper: asyncio.Task[None] | None = None
        self.port = 0

    @property
    def uri(self) -> str:
        """``http://<advertised host>:<port>/``; valid once started."""
        if not self.port:
            raise RuntimeError("the XML-RPC server has not been started")
        return http_uri(self.advertised_host, self.port)

    async def start(self) -> None:
        """Start listening (again on the same port, if it was started before).

        Raises:
            OSError: the address cannot be bound (``errno.EADDRINUSE`` if the port is taken).
        """
        loop = asyncio.get_running_loop()
        listener = descriptors.Listener(loop, self._accepted)
        for sock in descriptors.tcp_listeners(self.host, self.port or self._requested_port):
            listener.listen(sock)
        self._listener = listener
        self.port = listener.sockets[0].getsockname()[1]
        descriptors.watch(self)
        if self._sweeper is None:
            self._sweeper = loop.create_task(self._sweep())

    def stop_listening(self) -> None:
        """Refuse new connections from now on; calls under way still get their replies."""
        if self._listener is not None:
            self._listener.close()

    async def close(self) -> None:
        """Stop listening and close every connection."""
        listener, self._listener = self._listener, None
        sweeper, self._sweeper = self._sweeper, None
        descriptors.forget(self)
        if sweeper is not None:
            sweeper.cancel()
        if listener is not None:
            listener.close()
        tasks = list(self._connections)
        for task in tasks:
            task.cancel()
        if tasks:
            await asyncio.gather(*tasks, return_exceptions=True)

    # -- connections --------------------------------------------------------------------------

    async def _sweep(self) -> None:
        """Close connections silent for `idle_timeout`, checked a few times per timeout (one
        timer per server rather than one per read keeps the per-call cost at a clock read)."""
        loop = asyncio.get_running_loop()
        period = max(self.idle_timeout / 4, 0.05)
        while True:
            await asyncio.sleep(period)
            limit = loop.time() - self.idle_timeout
            for task, since in list(self._connections.items()):
                if since is not None and since < limit:
                    task.cancel()

    def idle_connections(self) -> Iterator[tuple[float, Callable[[], object]]]:
        """Connections waiting for a call, with when they last received bytes: what
        `rosx.transport.descriptors` may close when descriptors run short."""
        for task, since in self._connections.items():
            if since is not None:
                yield since, task.cancel

    def _accepted(self, sock: socket.socket) -> None:
        loop = asyncio.get_running_loop()
        task = loop.create_task(self._serve(sock))
        self._connections[task] = loop.time()
        task.add_done_callback(lambda task: self._ended(task, sock))

    def _ended(self, task: asyncio.Task[None], sock: socket.socket) -> None:
        """A connection's task is done. One cancelled before its first step never ran `_serve`,
        whose ``finally`` forgets the connection and closes its socket, so that is done here:
        a burst accepted in one turn of the loop near the descriptor limit is shed before its
        tasks start, and their sockets stayed open and listed as idle for good."""
        if task in self._connections:  # still listed: `_serve` never ran
            del self._connections[task]
            sock.close()

    async def _serve(self, sock: socket.socket) -> None:
        task = asyncio.current_task()
        assert task is not None
        writer: asyncio.StreamWriter | None = None
        try:
            reader, writer = await asyncio.open_connection(sock=sock, limit=_READ_SIZE)
            await self._serve_requests(task, reader, writer)
        except (ConnectionError, TimeoutError, asyncio.CancelledError):
            pass  # the peer went away, the server is closing, or the connection was idle
        except OSError as exc:
            _log.debug("XML-RPC connection failed: %s", exc)
        finally:
            self._connections.pop(task, None)
            if writer is not None:
                writer.close()
            else:
                sock.close()

    async def _serve_requests(
        self,
        task: asyncio.Task[None],
        reader: asyncio.StreamReader,
        writer: asyncio.StreamWriter,
    ) -> None:
        requests = RequestReader(max_body_size=self._max_body_size)
        clock = asyncio.get_running_loop().time
        connections = self._connections
        while True:
            try:
                request = requests.next_request()
            except HttpError as exc:
                writer.write(build_error_response(exc.status, str(exc)))
                await writer.drain()
                return
            if request is None:
                data = await reader.read(_READ_SIZE)
                if not data:
                    return
                connections[task] = clock()
                requests.feed(data)
                continue
            if request.method != "POST":
                writer.write(build_error_response(501, f"Unsupported method ({request.method!r})"))
                await writer.drain()
                return
            connections[task] = None
            body = await self.respond(request.body)
            writer.write(build_response(body, keep_alive=request.keep_alive))
            await writer.drain()
            if not request.keep_alive:
                return
            connections[task] = clock()

    # -- calls ----------------------------------------------------------------------------------

    async def respond(self, body: bytes) -> bytes:
        """The ``methodResponse`` document answering the ``methodCall`` document `body`."""
        try:
            call = decode_call(body)
        except ProtocolError as exc:
            return encode_fault(*_python_fault(exc))
        try:
            result = await self._invoke(call.method, call.params)
        except FaultError as exc:
            return encode_fault(exc.code, exc.message)
        except Exception as exc:  # any handler bug becomes a fault, never fatal
            # Often the caller's mistake (wrong arity, say): logged quietly, answered loudly.
            _log.debug("XML-RPC handler %s failed", call.method, exc_info=True)
            return encode_fault(*_python_fault(exc))
        if isinstance(result, EncodedResponse):
            return result.body
        try:
            return encode_response(result)
        except ProtocolError as exc:
            _log.error("XML-RPC handler %s returned an unencodable value: %s", call.method, exc)
            if isinstance(exc, UnencodableError):  # rosmaster's and rospy's answer, word for word
                return encode_fault(1, exc.python_fault)
            return encode_fault(*_python_fault(exc))

    async def _invoke(self, method: str, params: tuple[Any, ...] | list[Any]) -> Any:
        handler = self._methods.get(method)
        if handler is None:
            # SimpleXMLRPCServer's fault for an unknown method, word for word.
            raise FaultError(1, f"<class 'Exception'>:method \"{method}\" is not supported")
        result = handler(*params)
        if inspect.isawaitable(result):
            result = await result
        return result

    async def _multicall(self, calls: list[dict[str, Any]]) -> list[Any]:
        """``system.multicall``: each call's ``[value]``, or its fault as a struct."""
        results: list[Any] = []
        for entry in calls:
            try:
                result = await self._invoke(entry["methodName"], entry["params"])
            except FaultError as exc:
                results.append({"faultCode": exc.code, "faultString": exc.message})
            except Exception as exc:  # reported to the caller, as above
                code, message = _python_fault(exc)
                results.append({"faultCode": code, "faultString": message})
            else:
                value = result.value if isinstance(result, EncodedResponse) else result
                results.append([value])
        return results
