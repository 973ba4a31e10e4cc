"""A blocking XML-RPC client for command-line tools and nodes, with kept-alive connections.

`XmlRpcClient.call` sends one ``methodCall`` and returns the response's value. Each server
(host and port) gets connections that stay open between calls (HTTP/1.1 keep-alive, as ROS 1's
peers expect); a connection is used by one call at a time, so one client may be shared by
threads. A kept connection the server has meanwhile closed is replaced once, transparently.

Errors are typed (`rosx.transport.errors`): `ConnectError`, `CallTimeoutError`,
`BadReplyError` (all `TransportError`) and `FaultError`.

Cheap to import on purpose: a one-shot tool pays for `socket` and the wire codec only; no
`asyncio`, `threading` or `xmlrpc.client`.

    from rosx.transport.client import call
    code, status, pid = call("http://localhost:11311/", "getPid", "/rostopic", timeout=3.0)
"""

from __future__ import annotations

import _thread
import socket
import time

from rosx.transport.errors import BadReplyError, CallTimeoutError
from rosx.transport.exchange import (
    StaleConnectionError,
    bad_reply,
    connect_error,
    interpret,
    prepare,
)
from rosx.wire.errors import ProtocolError
from rosx.wire.xmlrpc_http import ResponseReader

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable
    from types import TracebackType
    from typing import Any

    from rosx.transport.exchange import Key
    from rosx.wire.xmlrpc_http import HttpResponse

#: Seconds a call may take, connecting included, unless the caller says otherwise.
DEFAULT_TIMEOUT = 10.0
_MAX_IDLE_PER_SERVER = 4
_RECV_SIZE = 1 << 16


class XmlRpcClient:
    """Calls XML-RPC methods over kept-alive connections, one pool per server."""

    def __init__(self, timeout: float = DEFAULT_TIMEOUT) -> None:
        self.timeout = timeout
        self._idle: dict[Key, list[socket.socket]] = {}
        # _thread rather than threading: importing threading costs a tool's start-up time.
        self._lock = _thread.allocate_lock()

    def call(self, uri: str, method: str, *params: object, timeout: float | None = None) -> Any:
        """Call `method` with `params` on the server at `uri` and return the reply's value.

        Args:
            uri: The server's ``http://host:port/`` URI.
            method: The XML-RPC method name.
            params: Its parameters (XML-RPC types: int, float, bool, str, bytes, list, dict).
            timeout: Seconds for the whole call; the client's default if ``None``.

        Raises:
            ConnectError: no connection could be opened.
            CallTimeoutError: no complete reply within `timeout`.
            BadReplyError: the reply is not an XML-RPC response.
            FaultError: the server answered with a fault.
            ProtocolError: a parameter cannot be carried by XML-RPC.
        """
        key, payload = prepare(uri, method, params)
        deadline = time.monotonic() + (self.timeout if timeout is None else timeout)
        sock = self._checkout(key)
        if sock is not None:
            try:
                return self._finish(uri, key, sock, self._exchange(uri, sock, payload, deadline))
            except StaleConnectionError:
                sock.close()
        sock = self._connect(uri, key, deadline)
        try:
            response = self._exchange(uri, sock, payload, deadline)
        except StaleConnectionError:
            sock.close()
            raise BadReplyError(uri, f"{uri} closed the connection without replying") from None
        return self._finish(uri, key, sock, response)

    def close(self) -> None:
        """Close every kept-alive connection (calls made later open new ones)."""
        with self._lock:
            idle, self._idle = self._idle, {}
        for socks in idle.values():
            for sock in socks:
                sock.close()

    def __enter__(self) -> XmlRpcClient:
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.close()

    # -- connections ------------------------------------------------------------------------

    def _checkout(self, key: Key) -> socket.socket | None:
        with self._lock:
            socks = self._idle.get(key)
            return socks.pop() if socks else None

    def _checkin(self, key: Key, sock: socket.socket) -> None:
        with self._lock:
            socks = self._idle.setdefault(key, [])
            if len(socks) < _MAX_IDLE_PER_SERVER:
                socks.append(sock)
                return
        sock.close()

    def _connect(self, uri: str, key: Key, deadline: float) -> socket.socket:
        try:
            host, port = key
            # create_connection hands the host to getaddrinfo, which takes bytes as well (typeshed
            # says str only): a str host is encoded with the idna codec, whose first use imports
            # unicodedata and stringprep, 3 ms of a one-shot tool's start-up; ASCII needs none.
            address = (host.encode("ascii") if host.isascii() else host, port)
            sock = socket.create_connection(address, timeout=_remaining(uri, deadline))  # type: ignore[arg-type]
        except TimeoutError:
            raise CallTimeoutError(uri, f"timed out connecting to {uri}") from None
        except OSError as exc:
            raise connect_error(uri, exc) from None
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        return sock

    def _finish(self, uri: str, key: Key, sock: socket.socket, response: HttpResponse) -> Any:
        if response.keep_alive:
            self._checkin(key, sock)
        else:
            sock.close()
        return interpret(uri, response)

    # -- one request ------------------------------------------------------------------------

    def _exchange(
        self, uri: str, sock: socket.socket, payload: bytes, deadline: float
    ) -> HttpResponse:
        """Send `payload`, read the response; `StaleConnectionError` if the peer closed at once."""
        reader = ResponseReader()
        received = False
        try:
            sock.settimeout(_remaining(uri, deadline))
            sock.sendall(payload)
            while True:
                response = reader.next_response()
                if response is not None:
                    return response
                sock.settimeout(_remaining(uri, deadline))
                data = sock.recv(_RECV_SIZE)
                if not data:
                    if not received:
                        raise StaleConnectionError
                    reader.feed_eof()
                    continue
                received = True
                reader.feed(data)
        except StaleConnectionError:
            raise
        except TimeoutError:
            sock.close()
            raise CallTimeoutError(uri, f"{uri} did not reply in time") from None
        except CallTimeoutError:
            sock.close()
            raise
        except (ConnectionResetError, BrokenPipeError) as exc:
            if not received:
                raise StaleConnectionError from None
            sock.close()
            raise bad_reply(uri, exc) from None
        except (OSError, ProtocolError) as exc:
            sock.close()
            raise bad_reply(uri, exc) from None


def _remaining(uri: str, deadline: float) -> float:
    left = deadline - time.monotonic()
    if left <= 0:
        raise CallTimeoutError(uri, f"{uri} did not reply in time")
    return left


class ServerProxy:
    """Calls as attributes, as `xmlrpc.client.ServerProxy`: ``ServerProxy(uri).getPid("/me")``."""

    def __init__(
        self, uri: str, *, timeout: float | None = None, client: XmlRpcClient | None = None
    ) -> None:
        self.uri = uri
        self.timeout = timeout
        self._client = client if client is not None else default_client()

    def __getattr__(self, method: str) -> Callable[..., Any]:
        if method.startswith("__"):
            raise AttributeError(method)

        def remote(*params: object) -> Any:
            return self._client.call(self.uri, method, *params, timeout=self.timeout)

        remote.__name__ = method
        return remote

    def __repr__(self) -> str:
        return f"ServerProxy({self.uri!r})"


_default: XmlRpcClient | None = None


def default_client() -> XmlRpcClient:
    """The process-wide client behind `call` and `ServerProxy` (its connections are shared)."""
    global _default  # noqa: PLW0603 -- one lazily created pool per process
    if _default is None:
        _default = XmlRpcClient()
    return _default


def call(uri: str, method: str, *params: object, timeout: float | None = None) -> Any:
    """`XmlRpcClient.call` on the process-wide client."""
    return default_client().call(uri, method, *params, timeout=timeout)
