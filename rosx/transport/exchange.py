"""One XML-RPC exchange as a client sees it, without I/O: the bytes to send, the reply to read.

Shared by the blocking client (`rosx.transport.client`) and the asyncio one
(`rosx.transport.aclient`), so both build requests and judge replies the same way.
"""

from __future__ import annotations

import errno

from rosx.transport.errors import BadReplyError, ConnectError, FaultError, InvalidUriError
from rosx.wire.errors import ProtocolError
from rosx.wire.xmlrpc import Fault, decode_response, encode_call
from rosx.wire.xmlrpc_http import build_request, parse_http_uri

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Iterable
    from typing import Any

    from rosx.wire.xmlrpc_http import HttpResponse

#: (host, port) of a server: connections are pooled per key.
Key = tuple[str, int]

_REASONS = {
    errno.ECONNREFUSED: "connection refused",
    errno.EHOSTUNREACH: "host unreachable",
    errno.ENETUNREACH: "network unreachable",
}


class StaleConnectionError(Exception):
    """A kept-alive connection was closed by the server before it answered: use a new one."""


def prepare(uri: str, method: str, params: Iterable[object]) -> tuple[Key, bytes]:
    """The connection key and the request bytes for calling `method` on the server at `uri`.

    Raises:
        InvalidUriError: `uri` is not an ``http://host:port/`` URI.
        ProtocolError: a parameter cannot be carried by XML-RPC (e.g. ``None``).
    """
    try:
        host, port, path = parse_http_uri(uri)
    except ProtocolError as exc:
        raise InvalidUriError(uri, f"cannot call {uri!r}: {exc}") from None
    authority = f"[{host}]:{port}" if ":" in host else f"{host}:{port}"
    return (host, port), build_request(authority, path, encode_call(method, params))


def connect_error(uri: str, exc: OSError) -> ConnectError:
    """The `ConnectError` for a failed connection attempt, naming the cause."""
    reason = _REASONS.get(exc.errno or 0) or exc.strerror or str(exc) or type(exc).__name__
    return ConnectError(uri, f"cannot connect to {uri}: {reason}", exc.errno)


def interpret(uri: str, response: HttpResponse) -> Any:
    """The value carried by `response`.

    Raises:
        BadReplyError: the response is an HTTP error or not a ``methodResponse``.
        FaultError: the server answered with a fault.
    """
    if response.status != 200:
        text = response.body[:200].decode("utf-8", "replace")
        raise BadReplyError(
            uri, f"{uri} answered HTTP {response.status} {response.reason}: {text}".rstrip(": ")
        )
    try:
        decoded = decode_response(response.body)
    except ProtocolError as exc:
        raise BadReplyError(uri, f"{uri} sent an invalid XML-RPC response: {exc}") from None
    if isinstance(decoded, Fault):
        raise FaultError(decoded.code, decoded.message, uri)
    return decoded.value


def bad_reply(uri: str, exc: Exception) -> BadReplyError:
    """The `BadReplyError` for a reply that broke off or did not parse."""
    if isinstance(exc, ProtocolError):
        return BadReplyError(uri, f"{uri} sent an invalid reply: {exc}")
    return BadReplyError(uri, f"connection to {uri} failed before a complete reply: {exc}")
