"""The client side of a ROS 1 service (ROS wiki ROS/TCPROS "Services"; rospy's ServiceProxy).

One blocking client for everyone who calls a service: nodes, the rospy-compatible API and
``rosservice``. Calls block the calling thread on a plain socket, as rospy's do: a service call
is one request and one answer, and doing it on the caller's thread costs no hand-off to the I/O
loop (nor the loop's import, for a command-line tool). Each call looks the service up at the
master (rospy does so every time, so a restarted server is found), connects, sends the client
header, *waits for the server's header* (rospy's server discards bytes that arrive with the
client's header), then sends the request and reads the ok byte and the answer
(`rosx.wire.rosrpc.ServiceReplyReader`). A persistent client keeps its connection for the next
call and looks the service up only to open a new one. A ``timeout`` bounds the whole exchange.

Failures raise `ServiceError` with rospy's texts: ``service [/x] unavailable``
(`ServiceUnavailable`), ``service [/x] has an invalid RPC URI [...]``, ``unable to connect to
service: ...``, ``transport error completing service call: ...``, ``service [/x] did not respond
within N seconds`` (`ServiceTimeout`) and, for ``ok=0``, ``service [/x] responded with an error:
<server's text>`` (`ServiceRefused`, which keeps the server's bytes).

`probe_service` opens a connection with ``probe=1`` and ``md5sum=*`` and returns the server's
header, which names the service's type (``rosservice type``); it fails with rosservice's
``Unable to communicate with service [/x], address [...]``.
"""

from __future__ import annotations

import _thread
import io
import socket
import time
from typing import TYPE_CHECKING, Any

from rosx.node.errors import ServiceError
from rosx.transport.errors import TransportError
from rosx.wire.errors import ProtocolError
from rosx.wire.framing import frame
from rosx.wire.header import Refused, encode_header
from rosx.wire.rosrpc import (
    ServerHeader,
    ServiceReplyReader,
    ServiceResponse,
    check_server_reply,
    client_header,
    parse_rosrpc_uri,
)

if TYPE_CHECKING:
    from rosx.master.client import MasterClient
    from rosx.msg.codec.message import Message, ServiceDefinition

#: Seconds to open a connection when the caller gives no timeout.
DEFAULT_CONNECT_TIMEOUT = 10.0
#: rosservice's socket timeout for a probe, in seconds.
PROBE_TIMEOUT = 5.0
_TERMINATED = "unable to receive data from sender, check sender's logs for details"


class ServiceUnavailable(ServiceError):  # noqa: N818 - rospy's condition, named as it says it
    """No node provides the service (the master does not know it)."""


class ServiceTimeout(ServiceError):  # noqa: N818 - a ServiceError, named for its cause
    """The service did not answer within the time the caller allowed."""


class ServiceRefused(ServiceError):  # noqa: N818 - a ServiceError, named for its cause
    """The server answered ``ok=0``; ``payload`` holds its error text, as sent."""

    def __init__(self, service: str, payload: bytes) -> None:
        text = payload.decode(errors="replace")
        super().__init__(f"service [{service}] responded with an error: {text}")
        self.service = service
        self.payload = payload


def lookup_service(master: MasterClient, name: str) -> str:
    """The ``rosrpc://`` URI of service ``name``.

    Raises:
        ServiceUnavailable: no node provides it.
        ServiceError: the master cannot be reached.
    """
    try:
        uri = master.lookup_service(name)
    except TransportError:
        raise ServiceError("unable to contact master") from None
    if uri is None:
        raise ServiceUnavailable(f"service [{name}] unavailable")
    return uri


def probe_service(
    master: MasterClient,
    name: str,
    *,
    uri: str | None = None,
    timeout: float | None = PROBE_TIMEOUT,
) -> dict[str, str]:
    """The header of the server of ``name`` (at ``uri``, else looked up), asked for with
    ``probe=1``: it names the service's type.

    Raises:
        ServiceUnavailable: no node provides the service.
        ServiceError: the server cannot be reached or closed without a header.
    """
    uri = lookup_service(master, name) if uri is None else uri
    fields = client_header(callerid=master.caller_id, service=name, md5sum="*", probe=True)
    deadline = _deadline(timeout)
    try:
        connection = _Connection.open(name, uri, fields, deadline, timeout)
        with connection:
            event = connection.read_event(deadline)
    except (TimeoutError, OSError, ProtocolError):
        event = None
    if not isinstance(event, ServerHeader):
        raise ServiceError(f"Unable to communicate with service [{name}], address [{uri}]")
    return event.fields


def contact_service(
    master: MasterClient, name: str, *, timeout: float = PROBE_TIMEOUT
) -> bool | None:
    """Whether service ``name`` answers a probe (``wait_for_service``'s question): None when
    the master knows no node providing it (or cannot be asked), False when it is registered
    but does not answer."""
    try:
        uri = lookup_service(master, name)
    except ServiceError:
        return None
    try:
        probe_service(master, name, uri=uri, timeout=timeout)
    except ServiceError:
        return False
    return True


class ServiceClient:
    """Calls one service by name (rospy's ``ServiceProxy``); safe to share between threads."""

    def __init__(
        self,
        master: MasterClient,
        name: str,
        service_class: type[ServiceDefinition],
        *,
        persistent: bool = False,
        headers: dict[str, str] | None = None,
        caller_id: str | None = None,
    ) -> None:
        self.master = master
        self.name = name
        self.service_class = service_class
        self.request_class = service_class._request_class
        self.response_class = service_class._response_class
        self.persistent = persistent
        self._fields = client_header(
            callerid=caller_id or master.caller_id,
            service=name,
            md5sum=service_class._md5sum,
            persistent=persistent,
        )
        if headers:
            self._fields.update(headers)
        # _thread rather than threading: rosservice pays for this import at start-up.
        self._lock = _thread.allocate_lock()
        self._connection: _Connection | None = None

    def call(self, request: Message, *, timeout: float | None = None) -> Any:
        """Send ``request`` and return the response message.

        Raises:
            TypeError: ``request`` is not of the service's request type.
            ServiceError: the call failed (see the module docstring for the texts).
        """
        if getattr(request, "_type", None) != self.request_class._type:
            raise TypeError(
                f"request object type [{type(request)}] does not match service type "
                f"[{self.request_class}]"
            )
        buff = io.BytesIO()
        request.serialize(buff)
        payload, header = self._exchange(buff.getvalue(), timeout)
        response = self.response_class().deserialize(payload)
        response._connection_header = header
        return response

    def call_serialized(self, request: bytes, *, timeout: float | None = None) -> bytes:
        """Send a serialized request; the serialized response (see `call`)."""
        return self._exchange(request, timeout)[0]

    def close(self) -> None:
        """Close a persistent connection (the next call opens a new one)."""
        with self._lock:
            if self._connection is not None:
                self._connection.close()
                self._connection = None

    def _exchange(self, request: bytes, timeout: float | None) -> tuple[bytes, dict[str, str]]:
        deadline = _deadline(timeout)
        with self._lock:
            connection = self._connection
            if connection is None:
                connection = self._connect(deadline, timeout)
            try:
                _until(connection.sock, deadline)
                connection.sock.sendall(frame(request))
                answer = connection.read_event(deadline)
            except TimeoutError:
                connection.close()
                self._connection = None
                raise self._timed_out(timeout) from None
            except (OSError, ProtocolError) as exc:
                connection.close()
                self._connection = None
                raise ServiceError(f"transport error completing service call: {exc}") from None
            if self.persistent and answer is not None:
                self._connection = connection
            else:
                connection.close()
                self._connection = None
        if answer is None:
            raise ServiceError(f"transport error completing service call: {_TERMINATED}")
        assert isinstance(answer, ServiceResponse)
        if not answer.ok:
            raise ServiceRefused(self.name, answer.payload)
        return answer.payload, connection.header

    def _connect(self, deadline: float | None, timeout: float | None) -> _Connection:
        """Look the service up, connect, exchange headers."""
        uri = lookup_service(self.master, self.name)
        md5sum = self.service_class._md5sum
        try:
            connection = _Connection.open(self.name, uri, self._fields, deadline, timeout)
        except TimeoutError:
            raise self._timed_out(timeout) from None
        except OSError as exc:
            raise ServiceError(f"unable to connect to service: {exc}") from None
        try:
            event = connection.read_event(deadline)
        except TimeoutError:
            connection.close()
            raise self._timed_out(timeout) from None
        except (OSError, ProtocolError) as exc:
            connection.close()
            raise ServiceError(f"unable to connect to service: {exc}") from None
        if event is None:
            connection.close()
            raise ServiceError(f"unable to connect to service: {_TERMINATED}")
        assert isinstance(event, ServerHeader)
        verdict = check_server_reply(event.fields, service=self.name, md5sum=md5sum)
        if isinstance(verdict, Refused):
            connection.close()
            reason = (
                f"remote error reported: {verdict.reason}" if verdict.by_peer else verdict.reason
            )
            raise ServiceError(f"unable to connect to service: {reason}")
        connection.header = event.fields
        return connection

    def _timed_out(self, timeout: float | None) -> ServiceError:
        if timeout is None:
            return ServiceError("unable to connect to service: timed out")
        return ServiceTimeout(f"service [{self.name}] did not respond within {timeout} seconds")


class _Connection:
    """One connected socket, its header sent, with the reader of what the server sends."""

    def __init__(self, sock: socket.socket) -> None:
        self.sock = sock
        self.reader = ServiceReplyReader()
        self.header: dict[str, str] = {}

    @classmethod
    def open(
        cls,
        name: str,
        uri: str,
        fields: dict[str, str],
        deadline: float | None,
        timeout: float | None,
    ) -> _Connection:
        """Connect to ``uri`` and send the client header ``fields``.

        Raises:
            ServiceError: ``uri`` is not a ``rosrpc://`` URI.
            TimeoutError: ``deadline`` passed.
            OSError: the connection failed.
        """
        try:
            host, port = parse_rosrpc_uri(uri)
        except ProtocolError:
            raise ServiceError(f"service [{name}] has an invalid RPC URI [{uri}]") from None
        sock = socket.create_connection(
            (host, port), timeout=DEFAULT_CONNECT_TIMEOUT if timeout is None else timeout
        )
        connection = cls(sock)
        try:
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            _until(sock, deadline)
            sock.sendall(encode_header(fields))
        except BaseException:
            sock.close()
            raise
        return connection

    def read_event(self, deadline: float | None) -> ServerHeader | ServiceResponse | None:
        """The next header or response; ``None`` when the server closed the connection first.

        Raises:
            TimeoutError: ``deadline`` passed.
        """
        while True:
            event = self.reader.next_event()
            if event is not None:
                return event
            _until(self.sock, deadline)
            data = self.sock.recv(65536)
            if not data:
                return None
            self.reader.feed(data)

    def close(self) -> None:
        self.sock.close()

    def __enter__(self) -> _Connection:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def _deadline(timeout: float | None) -> float | None:
    return None if timeout is None else time.monotonic() + timeout


def _until(sock: socket.socket, deadline: float | None) -> None:
    """Let the next socket operation wait until ``deadline`` at most (forever without one)."""
    if deadline is None:
        sock.settimeout(None)
        return
    left = deadline - time.monotonic()
    if left <= 0:
        raise TimeoutError
    sock.settimeout(left)
