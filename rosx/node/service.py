"""The server side of a ROS 1 service (ROS wiki ROS/TCPROS "Services", rospy's behaviour).

The node's TCPROS server hands over each connection whose header names this service and passed
`rosx.wire.rosrpc.accept_client`. `ServiceServer.serve` (on the loop) answers with the server
header, closes at once for a ``probe``, and otherwise reads requests and answers each one: one
request per connection, or as many as the client sends when it asked for ``persistent=1``.

Handlers run on a thread pool, never on the loop. What a handler returns becomes the response
by rospy's rules (`to_response`): a response instance as is, a dict as keyword fields, a list or
tuple as positional fields, any other value as the only field. A handler that raises
`ServiceError` answers ``ok=0`` with ``service cannot process request: <text>``; any other
exception with ``error processing request: <text>``, and is reported through ``on_exception``
(rospy's ``error_handler``) when given, else through ``on_error``.
"""

from __future__ import annotations

import asyncio
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.message import Message
from rosx.node.errors import ServiceError
from rosx.wire.framing import DEFAULT_MAX_FRAME_SIZE
from rosx.wire.header import encode_header
from rosx.wire.rosrpc import ServiceInfo, encode_error, encode_response

if TYPE_CHECKING:
    import socket
    from collections.abc import Callable
    from concurrent.futures import Executor

    from rosx.msg.codec.message import ServiceDefinition
    from rosx.transport.loop_thread import LoopThread
    from rosx.wire.framing import FrameReader
    from rosx.wire.rosrpc import ServiceClientAccepted


def to_response(value: object, response_class: type[Message]) -> Message:
    """A handler's return value as a response message, by rospy's rules.

    Raises:
        ServiceError: with rospy's text, when the value cannot become a response.
    """
    if isinstance(value, Message) and value._type == response_class._type:
        return value
    if isinstance(value, dict):
        try:
            return response_class(**value)
        except AttributeError as exc:
            raise ServiceError(f"handler returned invalid value: {exc}") from None
    if value is None:
        raise ServiceError("service handler returned None")
    if not isinstance(value, (list, tuple)):
        try:
            return response_class(value)
        except TypeError as exc:
            raise ServiceError(f"handler returned invalid value: {exc}") from None
    try:
        return response_class(*value)
    except TypeError as exc:
        raise ServiceError(f"handler returned wrong number of values: {exc}") from None


class ServiceServer:
    """One service a node provides (see the module's contract)."""

    def __init__(
        self,
        *,
        io: LoopThread,
        name: str,
        service_class: type[ServiceDefinition],
        handler: Callable[[Any], object],
        executor: Executor,
        on_error: Callable[[str], None] | None = None,
        on_exception: Callable[[Exception], object] | None = None,
    ) -> None:
        self.io = io
        self.name = name
        self.service_class = service_class
        self.handler = handler
        self._executor = executor
        self._on_error = on_error
        self._on_exception = on_exception
        request_class = service_class._request_class
        response_class = service_class._response_class
        self.info = ServiceInfo(
            name,
            service_class._type,
            service_class._md5sum,
            request_class._type,
            response_class._type,
        )
        self.uri = ""
        self.calls = 0
        self.closed = False
        self._tasks: set[asyncio.Task[Any]] = set()

    def handle(self, payload: bytes, header: dict[str, str]) -> bytes:
        """Answer one serialized request with the ok byte and a frame (on a pool thread)."""
        try:
            request = self.service_class._request_class().deserialize(payload)
            request._connection_header = header
            response = to_response(self.handler(request), self.service_class._response_class)
            buff = _Buffer()
            response.serialize(buff)
            return encode_response(b"".join(buff.parts))
        except ServiceError as exc:
            return encode_error(f"service cannot process request: {exc}")
        except Exception as exc:  # the client gets the text; the server goes on
            self._report(exc)
            return encode_error(f"error processing request: {exc}")

    def _report(self, exc: Exception) -> None:
        if self._on_exception is not None:
            try:
                self._on_exception(exc)
            except Exception as failure:  # a failing error handler must not stop the answer
                if self._on_error is not None:
                    self._on_error(f"Error handler of [{self.name}] failed: {failure}")
        elif self._on_error is not None:
            self._on_error(f"Error processing request: {exc}")

    async def serve(
        self,
        sock: socket.socket,
        accepted: ServiceClientAccepted,
        header: dict[str, str],
        reader: FrameReader,
    ) -> None:
        """Serve one client connection until it is done (on the loop).

        ``header`` is the client's; ``reader`` holds whatever followed it.
        """
        loop = self.io.loop
        task = asyncio.current_task()
        if task is not None:
            self._tasks.add(task)
        reader.max_frame_size = DEFAULT_MAX_FRAME_SIZE
        try:
            await loop.sock_sendall(sock, encode_header(accepted.reply))
            if accepted.probe:
                return
            while not self.closed:
                payload = reader.next_frame()
                if payload is None:
                    data = await loop.sock_recv(sock, 65536)
                    if not data:
                        return
                    reader.feed(data)
                    continue
                self.calls += 1
                answer = await loop.run_in_executor(self._executor, self.handle, payload, header)
                await loop.sock_sendall(sock, answer)
                if not accepted.persistent:
                    return
        except (OSError, asyncio.CancelledError):
            return
        finally:
            if task is not None:
                self._tasks.discard(task)
            sock.close()

    def close(self) -> None:
        """Stop serving: connections in progress are dropped. On the loop."""
        self.closed = True
        for task in list(self._tasks):
            task.cancel()


class _Buffer:
    """The cheapest writable for `Message.serialize`: it keeps the parts."""

    __slots__ = ("parts",)

    def __init__(self) -> None:
        self.parts: list[bytes] = []

    def write(self, data: bytes) -> None:
        self.parts.append(data)
