"""Errors raised by the XML-RPC transport.

A call either returns the server's value, or raises one of:

* `ConnectError`: no connection could be opened (refused, unreachable, unknown host), or
  none was tried since the URI is not an ``http://host:port/`` one (`InvalidUriError`);
* `CallTimeoutError`: no complete reply arrived in time;
* `BadReplyError`: the peer answered with something that is not an XML-RPC response (an HTTP
  error, malformed XML, a connection closed half-way);
* `FaultError`: the server ran the call and answered with an XML-RPC fault.

The first three are `TransportError`s: the call may not have reached the server. A `FaultError`
is not: the server answered. Servers raise `FaultError` from a handler to answer with a chosen
fault.
"""

from __future__ import annotations


class TransportError(Exception):
    """An XML-RPC call to `uri` did not get a usable reply."""

    def __init__(self, uri: str, message: str) -> None:
        super().__init__(message)
        self.uri = uri
        self.message = message


class ConnectError(TransportError):
    """No connection to the server at `uri` could be opened; `errno` says why, when known."""

    def __init__(self, uri: str, message: str, errno: int | None = None) -> None:
        super().__init__(uri, message)
        self.errno = errno


class InvalidUriError(ConnectError):
    """`uri` is not an ``http://host:port/`` URI (a peer may register any string): not called."""


class CallTimeoutError(TransportError):
    """The server at `uri` did not send a complete reply within the timeout."""


class BadReplyError(TransportError):
    """The server at `uri` answered with something that is not an XML-RPC response."""


class FaultError(Exception):
    """An XML-RPC fault: ``faultCode`` `code` and ``faultString`` `message`."""

    def __init__(self, code: int, message: str, uri: str = "") -> None:
        super().__init__(f"<Fault {code}: {message!r}>")
        self.code = code
        self.message = message
        self.uri = uri
