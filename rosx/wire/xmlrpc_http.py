"""HTTP/1.1 framing for XML-RPC, as the XML-RPC specification and RFC 9112 describe it.

XML-RPC travels as an HTTP ``POST`` whose body is the ``methodCall`` document; the answer is a
``200`` response whose body is the ``methodResponse``. ROS 1's master and nodes keep connections
open between calls (HTTP/1.1 keep-alive) unless a side says ``Connection: close``.

This module builds requests and responses as bytes and parses them incrementally from bytes fed
in any chunking (`RequestReader` on the server side, `ResponseReader` on the client side). It
supports what XML-RPC peers send: a ``Content-Length`` body (or, for a response, a body that ends
when the connection does). Chunked transfer coding, which no ROS 1 peer uses, is refused. Lines
end with CRLF. Header names are lowercased in the parsed events.

Headers are written as roscpp's XmlRpc++ expects: it finds the body length by looking for the
exact text ``Content-length: `` (case-insensitively) and keeps a connection open only after an
``HTTP/1.1 200 OK`` status line.
"""

from __future__ import annotations

from rosx.record import Record
from rosx.wire._digits import is_ascii_number
from rosx.wire.errors import HttpError, ProtocolError

#: Largest head (start line and headers) accepted, in bytes.
DEFAULT_MAX_HEAD_SIZE = 64 * 1024
#: Largest body accepted, in bytes; parameter trees and the master's replies stay far below it.
DEFAULT_MAX_BODY_SIZE = 100 * 1024 * 1024

_REASONS = {
    200: "OK",
    400: "Bad Request",
    404: "Not Found",
    405: "Method Not Allowed",
    411: "Length Required",
    413: "Content Too Large",
    431: "Request Header Fields Too Large",
    500: "Internal Server Error",
    501: "Not Implemented",
    505: "HTTP Version Not Supported",
}
_AGENT = "rosx"


class HttpRequest(Record):
    """A complete request: ``headers`` maps lowercased names to values."""

    __match_args__ = ("method", "target", "version", "headers", "body", "keep_alive")
    __slots__ = __match_args__
    method: str
    target: str
    version: str
    headers: dict[str, str]
    body: bytes
    keep_alive: bool

    def __init__(
        self,
        *,
        method: str,
        target: str,
        version: str,
        headers: dict[str, str],
        body: bytes,
        keep_alive: bool,
    ) -> None:
        super().__init__(
            method=method,
            target=target,
            version=version,
            headers=headers,
            body=body,
            keep_alive=keep_alive,
        )


class HttpResponse(Record):
    """A complete response: ``headers`` maps lowercased names to values."""

    __match_args__ = ("status", "reason", "version", "headers", "body", "keep_alive")
    __slots__ = __match_args__
    status: int
    reason: str
    version: str
    headers: dict[str, str]
    body: bytes
    keep_alive: bool

    def __init__(
        self,
        *,
        status: int,
        reason: str,
        version: str,
        headers: dict[str, str],
        body: bytes,
        keep_alive: bool,
    ) -> None:
        super().__init__(
            status=status,
            reason=reason,
            version=version,
            headers=headers,
            body=body,
            keep_alive=keep_alive,
        )


# -- building ---------------------------------------------------------------------------------


def parse_http_uri(uri: str) -> tuple[str, int, str]:
    """Split an ``http://host[:port][/path]`` URI (a ROS master or node URI) into its parts.

    The port defaults to 80 and the path to ``/``; an IPv6 host keeps no brackets.

    Raises:
        ProtocolError: the URI is not http or its port is invalid.
    """
    scheme, sep, rest = uri.partition("://")
    if not sep or scheme.lower() != "http":
        raise ProtocolError(f"not an http:// URI: {uri!r}")
    slash = rest.find("/")
    authority, path = (rest, "/") if slash < 0 else (rest[:slash], rest[slash:])
    authority = authority.rpartition("@")[2]
    if authority.startswith("["):
        host, bracket, after = authority[1:].partition("]")
        if not bracket:
            raise ProtocolError(f"invalid host or port in URI {uri!r}")
        port_text = after[1:] if after.startswith(":") else after
    else:
        host, _, port_text = authority.partition(":")
    if not host or (port_text and not is_ascii_number(port_text)) or int(port_text or 80) > 0xFFFF:
        raise ProtocolError(f"invalid host or port in URI {uri!r}")
    return host, int(port_text or 80), path


def build_request(host: str, path: str, body: bytes, *, keep_alive: bool = True) -> bytes:
    """An XML-RPC ``POST`` of `body` to `path` on `host` (``name:port`` as in the URI)."""
    connection = "" if keep_alive else "Connection: close\r\n"
    head = (
        f"POST {path or '/'} HTTP/1.1\r\nHost: {host}\r\nUser-Agent: {_AGENT}\r\n"
        f"Content-Type: text/xml\r\nContent-Length: {len(body)}\r\n{connection}\r\n"
    )
    return head.encode("latin-1") + body


def build_response(body: bytes, *, keep_alive: bool = True) -> bytes:
    """A ``200 OK`` response carrying an XML-RPC `body`."""
    connection = "" if keep_alive else "Connection: close\r\n"
    head = (
        f"HTTP/1.1 200 OK\r\nServer: {_AGENT}\r\nContent-Type: text/xml\r\n"
        f"Content-Length: {len(body)}\r\n{connection}\r\n"
    )
    return head.encode("latin-1") + body


def build_error_response(status: int, message: str = "") -> bytes:
    """A plain-text error response that closes the connection (e.g. 400, 404, 411, 501)."""
    reason = _REASONS.get(status, "Error")
    text = (message or reason).encode()
    head = (
        f"HTTP/1.1 {status} {reason}\r\nServer: {_AGENT}\r\n"
        f"Content-Type: text/plain; charset=utf-8\r\nContent-Length: {len(text)}\r\n"
        "Connection: close\r\n\r\n"
    )
    return head.encode("latin-1") + text


# -- parsing ----------------------------------------------------------------------------------


def _parse_fields(lines: list[bytes]) -> dict[str, str]:
    headers: dict[str, str] = {}
    for line in lines:
        if line[:1] in (b" ", b"\t"):
            raise HttpError(400, "obsolete line folding in HTTP headers is not accepted")
        name, colon, value = line.decode("latin-1").partition(":")
        if not colon or not name or name != name.strip():
            raise HttpError(400, f"malformed HTTP header line {line[:80]!r}")
        key = name.lower()
        text = value.strip(" \t")
        if key == "content-length" and key in headers and headers[key] != text:
            raise HttpError(400, "conflicting Content-Length headers")
        headers[key] = (
            f"{headers[key]}, {text}" if key in headers and key != "content-length" else text
        )
    return headers


def _keep_alive(version: str, headers: dict[str, str]) -> bool:
    tokens = {token.strip().lower() for token in headers.get("connection", "").split(",")}
    if "close" in tokens:
        return False
    return version == "HTTP/1.1" or "keep-alive" in tokens


def _body_length(headers: dict[str, str], limit: int) -> int | None:
    """The declared body length, or ``None`` if the message declares none."""
    if "transfer-encoding" in headers:
        raise HttpError(
            501, "chunked or other transfer codings are not supported; send Content-Length"
        )
    text = headers.get("content-length")
    if text is None:
        return None
    if not is_ascii_number(text):
        raise HttpError(400, f"invalid Content-Length {text!r}")
    length = int(text)
    if length > limit:
        raise HttpError(413, f"body of {length} bytes exceeds the limit of {limit} bytes")
    return length


class _Reader:
    """Shared buffering: find a head ending in a blank line, then a body of known length."""

    __slots__ = ("_buf", "_scanned", "max_body_size", "max_head_size")

    def __init__(self, max_head_size: int, max_body_size: int) -> None:
        self.max_head_size = max_head_size
        self.max_body_size = max_body_size
        self._buf = bytearray()
        self._scanned = 0  # the head's end was not found before this offset

    def feed(self, data: bytes | bytearray | memoryview) -> None:
        """Add bytes received from the peer."""
        self._buf += data

    def _take_head(self) -> list[bytes] | None:
        """Remove and return the head's lines (start line first), or None if incomplete."""
        buf = self._buf
        end = buf.find(b"\r\n\r\n", self._scanned)
        if end < 0:
            if len(buf) > self.max_head_size:
                raise HttpError(431, f"HTTP head exceeds {self.max_head_size} bytes")
            self._scanned = max(0, len(buf) - 3)
            return None
        if end > self.max_head_size:
            raise HttpError(431, f"HTTP head exceeds {self.max_head_size} bytes")
        lines = bytes(buf[:end]).split(b"\r\n")
        del buf[: end + 4]
        self._scanned = 0
        return lines

    def _take_body(self, length: int) -> bytes | None:
        buf = self._buf
        if len(buf) < length:
            return None
        body = bytes(buf[:length])
        del buf[:length]
        return body


class RequestReader(_Reader):
    """Parses requests a server receives, one after another on a kept-alive connection."""

    __slots__ = ("_head",)

    def __init__(
        self,
        *,
        max_head_size: int = DEFAULT_MAX_HEAD_SIZE,
        max_body_size: int = DEFAULT_MAX_BODY_SIZE,
    ) -> None:
        super().__init__(max_head_size, max_body_size)
        self._head: tuple[str, str, str, dict[str, str], int] | None = None

    def next_request(self) -> HttpRequest | None:
        """The next complete request, or ``None`` until more bytes arrive.

        Raises:
            HttpError: the request is malformed or too large; its `status` says how to answer.
        """
        if self._head is None:
            lines = self._take_head()
            if lines is None:
                return None
            parts = lines[0].decode("latin-1").split(" ")
            if len(parts) != 3 or not parts[0] or not parts[1]:
                raise HttpError(400, f"malformed HTTP request line {lines[0][:80]!r}")
            method, target, version = parts
            if not version.startswith("HTTP/1."):
                raise HttpError(505, f"unsupported HTTP version {version!r}")
            headers = _parse_fields(lines[1:])
            length = _body_length(headers, self.max_body_size)
            if length is None:
                if method == "POST":
                    raise HttpError(411, "an XML-RPC POST needs a Content-Length header")
                length = 0
            self._head = (method, target, version, headers, length)
        method, target, version, headers, length = self._head
        body = self._take_body(length)
        if body is None:
            return None
        self._head = None
        return HttpRequest(
            method=method,
            target=target,
            version=version,
            headers=headers,
            body=body,
            keep_alive=_keep_alive(version, headers),
        )


class ResponseReader(_Reader):
    """Parses the responses a client receives; call `feed_eof` when the server closes."""

    __slots__ = ("_eof", "_head")

    def __init__(
        self,
        *,
        max_head_size: int = DEFAULT_MAX_HEAD_SIZE,
        max_body_size: int = DEFAULT_MAX_BODY_SIZE,
    ) -> None:
        super().__init__(max_head_size, max_body_size)
        self._head: tuple[int, str, str, dict[str, str], int | None] | None = None
        self._eof = False

    def feed_eof(self) -> None:
        """Note that the server closed the connection (it may end a body of undeclared length)."""
        self._eof = True

    def next_response(self) -> HttpResponse | None:
        """The next complete response, or ``None`` until more bytes (or the end) arrive.

        Raises:
            ProtocolError: the response is malformed or too large, or the connection ended
                in the middle of it.
        """
        while self._head is None:
            lines = self._take_head()
            if lines is None:
                if self._eof and self._buf:
                    raise ProtocolError("connection closed in the middle of an HTTP response head")
                return None
            version, _, rest = lines[0].decode("latin-1").partition(" ")
            code, _, reason = rest.partition(" ")
            if not version.startswith("HTTP/1.") or len(code) != 3 or not is_ascii_number(code):
                raise ProtocolError(f"malformed HTTP status line {lines[0][:80]!r}")
            if code.startswith("1"):
                continue  # interim response (100 Continue): the real one follows
            headers = _parse_fields(lines[1:])
            self._head = (
                int(code),
                reason,
                version,
                headers,
                _body_length(headers, self.max_body_size),
            )
        status, reason, version, headers, length = self._head
        if length is None:
            if not self._eof:
                if len(self._buf) > self.max_body_size:
                    raise HttpError(413, f"response body exceeds {self.max_body_size} bytes")
                return None
            length = len(self._buf)
        body = self._take_body(length)
        if body is None:
            if self._eof:
                raise ProtocolError(
                    f"connection closed after {len(self._buf)} of {length} HTTP body bytes"
                )
            return None
        self._head = None
        return HttpResponse(
            status=status,
            reason=reason,
            version=version,
            headers=headers,
            body=body,
            keep_alive="content-length" in headers and _keep_alive(version, headers),
        )
