"""ROSRPC: ROS 1 services over TCPROS (ROS wiki ROS/TCPROS, "Services"; ROS/Connection Header).

A client looks a service up at the master, gets a ``rosrpc://host:port`` URI, connects and sends
its header (``callerid``, ``service``, ``md5sum``, and ``persistent`` or ``probe`` when wanted).
The server answers with its header (``callerid``, ``md5sum``, ``type``, ``request_type``,
``response_type``, ``service``) or an ``error`` header. ``probe=1`` asks only for the header, as
``rosservice type`` does. Then the client sends each request as a frame (`framing.frame`) and the
server answers each with an *ok byte* (uint8): 1 followed by a frame holding the serialized
response, or 0 followed by a frame holding a UTF-8 error text. A connection without
``persistent=1`` carries one call.

A client sends its first request only once the server's header has arrived: rospy's server reads
the client's header with a buffered read and drops whatever bytes came with it.

`ServiceReplyReader` parses what a client receives (the header, then responses) fed in any
chunking. The texts of refusals are rospy's, word for word.
"""

from __future__ import annotations

import ipaddress
import struct

from rosx.record import Record
from rosx.wire._digits import is_ascii_number
from rosx.wire.errors import OversizedError, ProtocolError
from rosx.wire.framing import DEFAULT_MAX_FRAME_SIZE, DEFAULT_MAX_HEADER_SIZE
from rosx.wire.header import Refused, decode_header
from rosx.wire.tcpros import WILDCARD, check_reply

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Mapping

_U32 = struct.Struct("<I")
_OK_LEN = struct.Struct("<BI")
_ROSRPC = "rosrpc://"
_CLIENT_REQUIRED = ("service", "md5sum", "callerid")


class ServiceInfo(Record):
    """What a service server offers, as its connection header states it."""

    __match_args__ = ("service", "type", "md5sum", "request_type", "response_type")
    __slots__ = __match_args__
    service: str
    type: str
    md5sum: str
    request_type: str
    response_type: str

    def __init__(
        self,
        service: str,
        type: str,
        md5sum: str,
        request_type: str,
        response_type: str,
    ) -> None:
        super().__init__(
            service=service,
            type=type,
            md5sum=md5sum,
            request_type=request_type,
            response_type=response_type,
        )


class ServiceClientAccepted(Record):
    """The server accepted a client: send `reply`; then serve requests unless `probe`."""

    __match_args__ = ("callerid", "service", "persistent", "probe", "reply")
    __slots__ = __match_args__
    callerid: str
    service: ServiceInfo
    persistent: bool
    probe: bool
    reply: dict[str, str]

    def __init__(
        self,
        callerid: str,
        service: ServiceInfo,
        persistent: bool,
        probe: bool,
        reply: dict[str, str],
    ) -> None:
        super().__init__(
            callerid=callerid, service=service, persistent=persistent, probe=probe, reply=reply
        )


class ServiceServerAccepted(Record):
    """The client accepted the server's header; `header` holds every field it sent."""

    __match_args__ = ("callerid", "type", "md5sum", "header")
    __slots__ = __match_args__
    callerid: str | None
    type: str
    md5sum: str
    header: dict[str, str]

    def __init__(
        self,
        callerid: str | None,
        type: str,
        md5sum: str,
        header: dict[str, str],
    ) -> None:
        super().__init__(callerid=callerid, type=type, md5sum=md5sum, header=header)


class ServiceResponse(Record):
    """One answer to a request: the serialized response if `ok`, else a UTF-8 error text."""

    __match_args__ = ("ok", "payload")
    __slots__ = __match_args__
    ok: bool
    payload: bytes

    def __init__(self, ok: bool, payload: bytes) -> None:
        super().__init__(ok=ok, payload=payload)

    @property
    def error(self) -> str:
        """The server's error text (meaningful only when not `ok`)."""
        return self.payload.decode(errors="replace")


def format_rosrpc_uri(host: str, port: int) -> str:
    """``rosrpc://host:port``, the URI a service is registered under (``[host]`` for IPv6)."""
    if ":" in host and not host.startswith("["):
        host = f"[{host}]"
    return f"{_ROSRPC}{host}:{port}"


def _is_ipv6(host: str) -> bool:
    try:
        ipaddress.IPv6Address(host)
    except ValueError:
        return False
    return True


def parse_rosrpc_uri(uri: str) -> tuple[str, int]:
    """Split a ``rosrpc://host:port`` URI (a trailing path is ignored) into host and port.

    An IPv6 host comes in brackets, or bare as ROS 1's nodes write it (``rosrpc://::1:4000``:
    the port follows the last colon); the host is returned without brackets.

    Raises:
        ProtocolError: with rospy's texts, if the scheme is not rosrpc or host:port is invalid.
    """
    if not uri.startswith(_ROSRPC):
        raise ProtocolError(f"Invalid protocol for ROS service URL: {uri}")
    hostport = uri[len(_ROSRPC) :].partition("/")[0]
    if hostport.startswith("["):
        host, closed, rest = hostport[1:].partition("]")
        port = rest[1:] if closed and rest.startswith(":") else ""
        valid = _is_ipv6(host)
    else:
        host, _, port = hostport.rpartition(":")
        valid = ":" not in host or _is_ipv6(host)
    if not (valid and host and is_ascii_number(port)):
        raise ProtocolError(f"ROS service URL is invalid: {uri}")
    return host, int(port)


def client_header(
    *, callerid: str, service: str, md5sum: str, persistent: bool = False, probe: bool = False
) -> dict[str, str]:
    """The header a service client sends; a probe asks for any type (md5sum ``*``)."""
    fields = {"callerid": callerid, "service": service, "md5sum": WILDCARD if probe else md5sum}
    if persistent:
        fields["persistent"] = "1"
    if probe:
        fields["probe"] = "1"
    return dict(sorted(fields.items()))


def server_header(info: ServiceInfo, *, callerid: str) -> dict[str, str]:
    """The header a service server sends back to an accepted client."""
    return dict(
        sorted(
            {
                "callerid": callerid,
                "md5sum": info.md5sum,
                "type": info.type,
                "request_type": info.request_type,
                "response_type": info.response_type,
                "service": info.service,
            }.items()
        )
    )


def accept_client(
    request: Mapping[str, str], *, callerid: str, services: Mapping[str, ServiceInfo]
) -> ServiceClientAccepted | Refused:
    """Decide, on the server side, whether to serve the client whose header is `request`.

    Args:
        request: the client's decoded header.
        callerid: this node's name, sent back and named in refusals.
        services: this node's services by resolved name.
    """
    for name in _CLIENT_REQUIRED:
        if name not in request:
            return Refused(f"Missing required '{name}' field")
    name = request["service"]
    info = services.get(name)
    if info is None:
        return Refused(f"[{callerid}] is not a provider of  [{name}]")
    md5sum = request["md5sum"]
    if WILDCARD not in (md5sum, info.md5sum) and md5sum != info.md5sum:
        return Refused(
            f"request from [{request['callerid']}]: md5sums do not match: "
            f"[{md5sum}] vs. [{info.md5sum}]"
        )
    return ServiceClientAccepted(
        callerid=request["callerid"],
        service=info,
        persistent=request.get("persistent", "").lower() in ("1", "true"),
        probe=request.get("probe") == "1",
        reply=server_header(info, callerid=callerid),
    )


def check_server_reply(
    reply: Mapping[str, str], *, service: str, md5sum: str
) -> ServiceServerAccepted | Refused:
    """Decide, on the client side, whether the server's header lets the call proceed."""
    refused = check_reply(reply, md5sum=md5sum, what="service", name=service)
    if refused is not None:
        return refused
    return ServiceServerAccepted(
        callerid=reply.get("callerid"),
        type=reply["type"],
        md5sum=reply["md5sum"],
        header=dict(reply),
    )


def encode_response(payload: bytes | bytearray | memoryview) -> bytes:
    """A successful answer: ok byte 1, then the serialized response as a frame."""
    data = bytes(payload)
    return _OK_LEN.pack(1, len(data)) + data


def encode_error(message: str) -> bytes:
    """A failed answer: ok byte 0, then the UTF-8 error text as a frame."""
    text = message.encode()
    return _OK_LEN.pack(0, len(text)) + text


class ServerHeader(Record):
    """The service server's decoded connection header, the first thing a client receives."""

    __match_args__ = ("fields",)
    __slots__ = __match_args__
    fields: dict[str, str]

    def __init__(self, fields: dict[str, str]) -> None:
        super().__init__(fields=fields)


class ServiceReplyReader:
    """Parses the bytes a service client receives: one header, then responses.

    `feed` bytes in any chunking, then call `next_event` until it returns ``None`` (more bytes
    needed). The first event is a `ServerHeader`; every later one a `ServiceResponse`. Pass
    ``expect_header=False`` to read responses only.
    """

    __slots__ = ("_buf", "_header_pending", "max_header_size", "max_response_size")

    def __init__(
        self,
        *,
        expect_header: bool = True,
        max_header_size: int = DEFAULT_MAX_HEADER_SIZE,
        max_response_size: int = DEFAULT_MAX_FRAME_SIZE,
    ) -> None:
        self.max_header_size = max_header_size
        self.max_response_size = max_response_size
        self._header_pending = expect_header
        self._buf = bytearray()

    def feed(self, data: bytes | bytearray | memoryview) -> None:
        """Add bytes received from the server."""
        self._buf += data

    def next_event(self) -> ServerHeader | ServiceResponse | None:
        """The next complete header or response, or ``None`` until more bytes arrive.

        Raises:
            ProtocolError: the header is malformed.
            OversizedError: a length exceeds the configured maximum.
        """
        buf = self._buf
        if self._header_pending:
            if len(buf) < 4:
                return None
            (size,) = _U32.unpack_from(buf, 0)
            if size > self.max_header_size:
                raise OversizedError("service connection header", size, self.max_header_size)
            if len(buf) < 4 + size:
                return None
            fields = decode_header(bytes(buf[4 : 4 + size]))
            del buf[: 4 + size]
            self._header_pending = False
            return ServerHeader(fields)
        if len(buf) < 5:
            return None
        ok, size = _OK_LEN.unpack_from(buf, 0)
        if size > self.max_response_size:
            raise OversizedError("service response", size, self.max_response_size)
        if len(buf) < 5 + size:
            return None
        payload = bytes(buf[5 : 5 + size])
        del buf[: 5 + size]
        return ServiceResponse(ok=ok != 0, payload=payload)
