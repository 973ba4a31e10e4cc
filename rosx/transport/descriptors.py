"""A process's reserve of file descriptors, and the idle connections given up to keep it.

A process may hold ``RLIMIT_NOFILE`` descriptors (1 024 by default on Linux). A server that
lets them run out cannot accept anyone any more: not the tool that asks the master one
question, not the subscriber of a node's topic. rosmaster and ROS 1's nodes then stall until
clients give up their connections, and idle connections (an abandoned keep-alive, a port
scanner, a peer that hung) never do.

rosx's servers accept through `Listener`, which keeps `reserve` descriptors free: when a
newly accepted socket's descriptor is within the reserve of the limit (Linux hands out the
lowest free number, so descriptor ``n`` means ``n`` others are open), or when ``accept`` fails
for want of descriptors, the oldest idle connections of all the process's servers are closed
(`shed`), never a connection whose call is being answered, and the server goes on accepting.
The first time, the process's log says so in one warning.

A server takes part by registering a `Sheddable` (`watch`): something that lists its idle
connections, each with the time it fell idle and a callable that closes it. Everything here
runs on the process's event loop (`rosx.transport.loop_thread`).
"""

from __future__ import annotations

import errno
import logging
import socket
import weakref
from typing import Protocol

TYPE_CHECKING = False
if TYPE_CHECKING:
    import asyncio
    from collections.abc import Callable, Iterable

try:
    import resource
except ImportError:  # Windows: no descriptor limit to watch (select's own limit applies)
    resource = None  # type: ignore[assignment]

_log = logging.getLogger(__name__)

#: ``accept`` errors that mean "no descriptor or memory left for the new socket".
_EXHAUSTED = frozenset({errno.EMFILE, errno.ENFILE, errno.ENOBUFS, errno.ENOMEM})
#: Seconds before listening again when accepting failed and nothing could be closed.
ACCEPT_PAUSE = 0.05
#: Connections the kernel queues for a listening socket before it is accepted from. A burst
#: longer than the queue (a launch starting a hundred nodes, a thousand idle connections) has
#: its handshakes dropped, and each such client waits a second for its next try.
BACKLOG = 1024


class Sheddable(Protocol):
    """A server whose idle connections may be closed to free descriptors."""

    def idle_connections(self) -> Iterable[tuple[float, Callable[[], object]]]:
        """Each idle connection: when it fell idle (the loop's clock) and how to close it."""
        ...  # pragma: no cover - a protocol


_sources: weakref.WeakSet[Sheddable] = weakref.WeakSet()
_warned = False


def watch(source: Sheddable) -> None:
    """Offer ``source``'s idle connections when the process runs short of descriptors."""
    _sources.add(source)


def forget(source: Sheddable) -> None:
    """Stop offering ``source``'s connections (it is closing)."""
    _sources.discard(source)


def limit() -> int:
    """The process's descriptor limit (``RLIMIT_NOFILE``'s soft value); 0 when unknown."""
    if resource is None:
        return 0
    soft, _ = resource.getrlimit(resource.RLIMIT_NOFILE)
    return 0 if soft == resource.RLIM_INFINITY else int(soft)


def reserve(limit: int) -> int:
    """Descriptors kept free under ``limit``: 1/16th of it, between 8 and 128.

    Enough for a burst of legitimate connections, the files a node opens and the connections
    it makes itself while its servers free more.
    """
    return max(8, min(128, limit // 16))


def shed(in_use: int, limit: int) -> int:
    """Close the oldest idle connections so that about two reserves are free; returns how many.

    Args:
        in_use: How many descriptors the process holds (at least).
        limit: The process's descriptor limit.
    """
    wanted = in_use - (limit - 2 * reserve(limit))
    if wanted <= 0:
        return 0
    idle: list[tuple[float, Callable[[], object]]] = []
    for source in list(_sources):
        idle.extend(source.idle_connections())
    idle.sort(key=lambda entry: entry[0])
    closing = idle[:wanted]
    for _, close in closing:
        close()
    _report(len(closing), in_use, limit)
    return len(closing)


def _report(closed: int, in_use: int, limit: int) -> None:
    global _warned  # noqa: PLW0603 - said once a process, as the module's contract says
    if _warned:
        _log.debug("descriptors low (%d of %d): closed %d idle connections", in_use, limit, closed)
        return
    _warned = True
    _log.warning(
        "%d of %d file descriptors in use: closing the %d oldest idle connections to keep "
        "serving (said once; raise the limit with `ulimit -n` if this is expected load)",
        in_use,
        limit,
        closed,
    )


class Listener:
    """Accepts connections on listening sockets for a server and keeps the descriptor reserve.

    Accepting is a reader callback of the loop, not a task awaiting `loop.sock_accept`: a
    connection that arrives as the server closes would then complete an accept whose future
    was cancelled, and asyncio prints that error's traceback (CPython 3.10-3.13).

    Args:
        loop: The loop the server runs on.
        on_connection: Called on the loop with each accepted, non-blocking socket.
    """

    def __init__(
        self,
        loop: asyncio.AbstractEventLoop,
        on_connection: Callable[[socket.socket], None],
    ) -> None:
        self._loop = loop
        self._on_connection = on_connection
        self.sockets: list[socket.socket] = []

    def listen(self, listener: socket.socket) -> None:
        """Accept on the non-blocking, listening ``listener`` (closed by `close`)."""
        self.sockets.append(listener)
        self._loop.add_reader(listener.fileno(), self._accept, listener)

    def close(self) -> None:
        """Stop accepting and close the listening sockets."""
        sockets, self.sockets = self.sockets, []
        for listener in sockets:
            if listener.fileno() >= 0:
                self._loop.remove_reader(listener.fileno())
                listener.close()

    def _accept(self, listener: socket.socket) -> None:
        """Take every connection waiting on ``listener``."""
        while listener.fileno() >= 0:
            try:
                sock, _ = listener.accept()
            except (BlockingIOError, InterruptedError):
                return
            except OSError as exc:
                self._exhausted(listener, exc)
                return
            sock.setblocking(False)
            most = limit()
            if most and sock.fileno() >= most - reserve(most):
                shed(sock.fileno() + 1, most)
            self._on_connection(sock)

    def _exhausted(self, listener: socket.socket, exc: OSError) -> None:
        # Free what idle connections hold and try again once they are closed (their closing
        # runs on the loop's next turn); with nothing to close, listen again a little later,
        # rather than spin on a socket that stays readable.
        most = limit()
        closed = shed(most, most) if most and exc.errno in _EXHAUSTED else 0
        self._loop.remove_reader(listener.fileno())
        if closed:
            self._loop.call_soon(self._resume, listener)
        else:
            self._loop.call_later(ACCEPT_PAUSE, self._resume, listener)

    def _resume(self, listener: socket.socket) -> None:
        if listener.fileno() >= 0 and listener in self.sockets:
            self._loop.add_reader(listener.fileno(), self._accept, listener)


def tcp_listeners(host: str, port: int, backlog: int = BACKLOG) -> list[socket.socket]:
    """Non-blocking sockets listening on every address of ``host`` at ``port`` (asyncio's
    ``start_server`` rules: address reuse, IPv6 sockets IPv6 only).

    Raises:
        OSError: an address cannot be bound (``errno.EADDRINUSE``: the port is taken).
    """
    infos = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE)
    sockets: list[socket.socket] = []
    seen: set[tuple[object, ...]] = set()
    try:
        for family, kind, proto, _, address in infos:
            if (family, address) in seen:
                continue
            seen.add((family, address))
            sock = socket.socket(family, kind, proto)
            sockets.append(sock)
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            if family == socket.AF_INET6:
                sock.setsockopt(socket.IPPROTO_IPV6, socket.IPV6_V6ONLY, 1)
            sock.bind(address)
            sock.listen(backlog)
            sock.setblocking(False)
    except OSError:
        for sock in sockets:
            sock.close()
        raise
    return sockets
