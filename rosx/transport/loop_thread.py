"""An asyncio event loop in a background thread, for synchronous callers of async servers.

`LoopThread` runs a fresh event loop in a daemon thread; `run` and `submit` hand it coroutines
from any other thread. `ServerThread` uses one to host an `XmlRpcServer` for code that does not
run an event loop of its own (tests, synchronous nodes, tools that serve a callback URI).

    with ServerThread({"getPid": lambda caller_id: [1, "", os.getpid()]}) as server:
        call(server.uri, "getPid", "/me")
"""

from __future__ import annotations

import asyncio
import threading

from rosx.transport.server import XmlRpcServer

TYPE_CHECKING = False
if TYPE_CHECKING:
    import concurrent.futures
    from collections.abc import Coroutine, Mapping
    from types import TracebackType
    from typing import Any, TypeVar

    from rosx.transport.server import Handler

    T = TypeVar("T")
    H = TypeVar("H", bound="Hosted")


class LoopThread:
    """An event loop running in its own daemon thread until `stop`."""

    def __init__(self, name: str = "rosx-loop") -> None:
        self.name = name
        self._loop: asyncio.AbstractEventLoop | None = None
        self._thread: threading.Thread | None = None

    @property
    def loop(self) -> asyncio.AbstractEventLoop:
        """The running loop (after `start`)."""
        if self._loop is None:
            raise RuntimeError(f"{self.name} has not been started")
        return self._loop

    @property
    def running(self) -> bool:
        """Whether the loop has been started and not stopped."""
        return self._loop is not None

    def start(self) -> asyncio.AbstractEventLoop:
        """Start the thread and its loop (idempotent); returns the loop."""
        if self._loop is None:
            loop = asyncio.new_event_loop()
            ready = threading.Event()
            self._thread = threading.Thread(
                target=self._run, args=(loop, ready), name=self.name, daemon=True
            )
            self._thread.start()
            ready.wait()
            self._loop = loop
        return self._loop

    @staticmethod
    def _run(loop: asyncio.AbstractEventLoop, ready: threading.Event) -> None:
        asyncio.set_event_loop(loop)
        loop.call_soon(ready.set)
        try:
            loop.run_forever()
        finally:
            pending = [task for task in asyncio.all_tasks(loop) if not task.done()]
            for task in pending:
                task.cancel()
            if pending:
                loop.run_until_complete(asyncio.gather(*pending, return_exceptions=True))
            loop.run_until_complete(loop.shutdown_asyncgens())
            loop.close()

    def submit(self, coro: Coroutine[Any, Any, T]) -> concurrent.futures.Future[T]:
        """Schedule `coro` on the loop; returns a future the calling thread can wait on."""
        return asyncio.run_coroutine_threadsafe(coro, self.loop)

    def run(self, coro: Coroutine[Any, Any, T], timeout: float | None = None) -> T:
        """Run `coro` on the loop and wait for its result (from another thread only)."""
        if threading.current_thread() is self._thread:
            raise RuntimeError("LoopThread.run called from its own loop; await instead")
        return self.submit(coro).result(timeout)

    def stop(self, timeout: float = 5.0) -> None:
        """Stop the loop (cancelling what still runs on it) and join the thread."""
        loop, thread = self._loop, self._thread
        self._loop = self._thread = None
        if loop is None or thread is None:
            return
        loop.call_soon_threadsafe(loop.stop)
        if thread is not threading.current_thread():
            thread.join(timeout)

    def __enter__(self) -> LoopThread:
        self.start()
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.stop()


class Hosted:
    """Something with async ``start()`` and ``close()`` and a ``uri``, hosted on a background
    `LoopThread` for synchronous callers: the shape of `ServerThread` and of the master's
    `rosx.master.server.MasterThread`."""

    def __init__(self, hosted: Any, name: str, close_timeout: float) -> None:
        self._hosted = hosted
        self._close_timeout = close_timeout
        self.loop_thread = LoopThread(name)

    @property
    def uri(self) -> str:
        """The URI it serves (after `start`)."""
        return str(self._hosted.uri)

    def start(self) -> str:
        """Start the loop thread and what it hosts; returns the URI.

        Raises:
            OSError: the address cannot be bound.
        """
        self.loop_thread.start()
        try:
            self.loop_thread.run(self._hosted.start())
        except BaseException:
            self.loop_thread.stop()
            raise
        return self.uri

    def run(self, coro: Coroutine[Any, Any, T], timeout: float | None = 10.0) -> T:
        """Run ``coro`` on the loop (to read or change the hosted object's state safely)."""
        return self.loop_thread.run(coro, timeout)

    def close(self) -> None:
        """Close what it hosts, then stop the loop thread."""
        if self.loop_thread.running:
            self.loop_thread.run(self._hosted.close(), timeout=self._close_timeout)
        self.loop_thread.stop()

    def __enter__(self: H) -> H:
        self.start()
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.close()


class ServerThread(Hosted):
    """An `XmlRpcServer` served from a background `LoopThread` (arguments as `XmlRpcServer`'s)."""

    def __init__(
        self,
        handlers: Mapping[str, Handler] | object,
        *,
        host: str = "127.0.0.1",
        port: int = 0,
        advertised_host: str | None = None,
        multicall: bool = False,
    ) -> None:
        self.server = XmlRpcServer(
            handlers, host=host, port=port, advertised_host=advertised_host, multicall=multicall
        )
        super().__init__(self.server, "rosx-xmlrpc", close_timeout=5.0)

    @property
    def port(self) -> int:
        """The port listened on (after `start`)."""
        return self.server.port
