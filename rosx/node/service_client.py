"""The client side of a ROS 1 service (ROS wiki ROS/TCPROS "Services"; rospy's ServiceProxy).

Calls block the calling thread on a plain socket, as rospy's do: a service call is one request
and one answer, and doing it on the caller's thread costs no hand-off to the I/O loop. Each
call looks the service up at the master (rospy does so every time, so a restarted server is
found), connects, sends the client header, *waits for the server's header* (rospy's server
discards bytes that arrive with the client's header), then sends the request and reads the ok
byte and the answer (`rosx.wire.rosrpc.ServiceReplyReader`). A persistent client keeps its
connection for the next call and looks the service up only to open a new one.

Failures raise `ServiceError` with rospy's texts: ``service [/x] unavailable``, ``unable to
connect to service: ...``, ``transport error completing service call: ...`` and, for ``ok=0``,
``service [/x] responded with an error: <server's text>``.

`probe_service` opens a connection with ``probe=1`` and ``md5sum=*`` and returns the server's
header, which names the service's type (``rosservice type``).
"""

from __future__ import annotations

import io
import socket
import threading
from typing import TYPE_CHECKING, Any

from rosx.node.errors import MasterError, ServiceError
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
    from rosx.msg.codec.message import Message, ServiceDefinition
    from rosx.node.master_proxy import MasterProxy

#: Seconds to connect and exchange headers when the caller gives no timeout.
DEFAULT_CONNECT_TIMEOUT = 10.0


def lookup_service(master: MasterProxy, name: str) -> str:
    """The ``rosrpc://`` URI of service ``name``; `ServiceError` if no node provides it."""
    try:
        uri = master.call("lookupService", name)
    except MasterError:
        raise ServiceError(f"service [{name}] unavailable") from None
    except TransportError:
        raise ServiceError("unable to contact master") from None
    return str(uri)


class _Connection:
    """One connected socket with the reader of what the server sends."""

    def __init__(self, sock: socket.socket, reader: ServiceReplyReader, header: dict[str, str]):
        self.sock = sock
        self.reader = reader
        self.header = header

    def read_event(self) -> ServerHeader | ServiceResponse:
        while True:
            event = self.reader.next_event()
            if event is not None:
                return event
            data = self.sock.recv(65536)
            if not data:
                raise ConnectionResetError("the service closed the connection")
            self.reader.feed(data)

    def close(self) -> None:
        self.sock.close()


def _open(
    uri: str, fields: dict[str, str], timeout: float | None, service: str, md5sum: str
) -> _Connection:
    try:
        host, port = parse_rosrpc_uri(uri)
    except ProtocolError as exc:
        raise ServiceError(f"master returned invalid ROSRPC URI: {uri}") from exc
    try:
        sock = socket.create_connection(
            (host, port), timeout=DEFAULT_CONNECT_TIMEOUT if timeout is None else timeout
        )
    except OSError as exc:
        raise ServiceError(f"unable to connect to service: {exc}") from None
    sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    connection = _Connection(sock, ServiceReplyReader(), {})
    try:
        sock.sendall(encode_header(fields))
        event = connection.read_event()
    except (OSError, ProtocolError) as exc:
        sock.close()
        raise ServiceError(f"unable to connect to service: {exc}") from None
    assert isinstance(event, ServerHeader)
    verdict = check_server_reply(event.fields, service=service, md5sum=md5sum)
    if isinstance(verdict, Refused):
        sock.close()
        raise ServiceError(f"unable to connect to service: remote error reported: {verdict.reason}")
    connection.header = event.fields
    sock.settimeout(timeout)
    return connection


def probe_service(
    master: MasterProxy, name: str, *, timeout: float | None = None
) -> dict[str, str]:
    """The header of the server of ``name``, asked for with ``probe=1`` (type discovery)."""
    uri = lookup_service(master, name)
    fields = client_header(callerid=master.caller_id, service=name, md5sum="*", probe=True)
    connection = _open(uri, fields, timeout, name, "*")
    connection.close()
    return connection.header


class ServiceClient:
    """Calls one service by name (rospy's ``ServiceProxy``); safe to share between threads."""

    def __init__(
        self,
        master: MasterProxy,
        name: str,
        service_class: type[ServiceDefinition],
        *,
        persistent: bool = False,
        headers: dict[str, str] | None = None,
    ) -> None:
        self.master = master
        self.name = name
        self.service_class = service_class
        self.request_class = service_class._request_class
        self.response_class = service_class._response_class
        self.persistent = persistent
        self._fields = client_header(
            callerid=master.caller_id,
            service=name,
            md5sum=service_class._md5sum,
            persistent=persistent,
        )
        if headers:
            self._fields.update(headers)
        self._lock = threading.Lock()
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
        payload = frame(_serialize(request))
        with self._lock:
            connection = self._connection
            if connection is None:
                uri = lookup_service(self.master, self.name)
                connection = _open(
                    uri, self._fields, timeout, self.name, self.service_class._md5sum
                )
            try:
                connection.sock.settimeout(timeout)
                connection.sock.sendall(payload)
                answer = connection.read_event()
            except (OSError, ProtocolError) as exc:
                connection.close()
                self._connection = None
                raise ServiceError(f"transport error completing service call: {exc}") from None
            if self.persistent:
                self._connection = connection
            else:
                connection.close()
        assert isinstance(answer, ServiceResponse)
        if not answer.ok:
            raise ServiceError(f"service [{self.name}] responded with an error: {answer.error}")
        response = self.response_class().deserialize(answer.payload)
        response._connection_header = connection.header
        return response

    def close(self) -> None:
        """Close a persistent connection (the next call opens a new one)."""
        with self._lock:
            if self._connection is not None:
                self._connection.close()
                self._connection = None


def _serialize(msg: Message) -> bytes:
    buff = io.BytesIO()
    msg.serialize(buff)
    return buff.getvalue()
