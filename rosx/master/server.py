"""The ROS master as an XML-RPC server: `MasterApi` behind `XmlRpcServer`, with a `Notifier`
for the calls it makes to nodes (ROS wiki Master_API, Parameter Server API).

`Master` runs in an asyncio event loop; `MasterThread` hosts one on the process's event loop
(`rosx.transport.loop_thread`) for synchronous code (`rosx.core`, tests, benchmarks). All master
state lives on the loop's thread; other threads reach it through the loop (`MasterThread.run`),
never directly.

A ``shutdown`` call from a client is passed to ``on_shutdown`` with the caller's message;
whoever runs the master decides when to `close` it, as roscore does.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

from rosx.master.api import MasterApi
from rosx.master.defaults import DEFAULT_MASTER_PORT
from rosx.master.notifier import DEFAULT_TIMEOUT, Notifier
from rosx.transport.address import http_uri
from rosx.transport.loop_thread import Hosted
from rosx.transport.server import XmlRpcServer

if TYPE_CHECKING:
    from collections.abc import Callable


class Master:
    """The master: `start` in a running loop, then `close`.

    Args:
        host: The address to listen on.
        port: The port (0 picks a free one).
        advertised_host: The host named in the master's URI (``getUri``).
        notify_timeout: Seconds a node has to answer each notification.
        pid: The process id ``getPid`` reports (this process by default).
        on_shutdown: Called with the message of a ``shutdown`` call (on the loop's thread).
    """

    def __init__(
        self,
        *,
        host: str = "127.0.0.1",
        port: int = DEFAULT_MASTER_PORT,
        advertised_host: str = "localhost",
        notify_timeout: float = DEFAULT_TIMEOUT,
        pid: int | None = None,
        on_shutdown: Callable[[str], None] | None = None,
    ) -> None:
        self._host = host
        self._port = port
        self._advertised_host = advertised_host
        self._notify_timeout = notify_timeout
        self.api = MasterApi(
            "", os.getpid() if pid is None else pid, on_shutdown=self._shutdown_called
        )
        self.notifier: Notifier | None = None
        self.server: XmlRpcServer | None = None
        self._on_shutdown = on_shutdown

    @property
    def uri(self) -> str:
        """``http://<advertised host>:<port>/`` (after `start`)."""
        return self.api.uri

    @property
    def port(self) -> int:
        """The port listened on (after `start`)."""
        if self.server is None:
            raise RuntimeError("the master has not been started")
        return self.server.port

    async def start(self) -> None:
        """Start serving.

        Raises:
            OSError: the address cannot be bound (``errno.EADDRINUSE``: the port is taken).
        """
        self.notifier = Notifier(timeout=self._notify_timeout)
        self.api.notify = self.notifier.submit
        server = XmlRpcServer(
            self.api.handlers(),
            host=self._host,
            port=self._port,
            advertised_host=self._advertised_host,
            multicall=True,
        )
        await server.start()
        self.server = server
        self.api.uri = http_uri(self._advertised_host, server.port)

    async def close(self) -> None:
        """Stop serving and drop pending notifications."""
        server, self.server = self.server, None
        if server is not None:
            await server.close()
        if self.notifier is not None:
            await self.notifier.close()

    def _shutdown_called(self, caller_id: str, message: str) -> None:
        if self._on_shutdown is not None:
            self._on_shutdown(message)


class MasterThread(Hosted):
    """A `Master` on the process's event loop; arguments as `Master`'s, but port 0 by default."""

    def __init__(self, *, port: int = 0, **options: Any) -> None:
        self.master = Master(port=port, **options)
        super().__init__(self.master, close_timeout=10.0)
