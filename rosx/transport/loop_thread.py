"""The event loop: an asyncio loop on a daemon thread, one per process, reached from any thread.

Every socket the process serves runs on one loop, `process_loop()`: the master's XML-RPC
server, each node's Slave API and TCPROS servers, publisher and subscriber connections. Hosting
a master and many nodes in one process (``rosx roscore``, ``rosx sim``, the tests) therefore
costs one I/O thread, not one per server. User code never runs on the loop: nodes run message
callbacks and service handlers on threads of their own (see `rosx.node`).

Synchronous callers reach the loop through `LoopThread.run` (wait for a coroutine's result),
`submit` (a future to wait on later), `call_soon` and `spawn` (fire and forget). Code already on
the loop's thread awaits or calls directly instead: `run` there would wait for itself, so it
raises `LoopThreadError`.

`Hosted` puts something with async ``start``/``close`` on the loop for synchronous code;
`ServerThread` is an `XmlRpcServer` hosted that way:

    with ServerThread({"getPid": lambda caller_id: [1, "", os.getpid()]}) as server:
        call(server.uri, "getPid", "/me")

The thread is a daemon: a process that forgets to close what it hosts still exits.
"""

from __future__ import annotations

import asyncio
import concurrent.futures
import threading

from rosx.transport.server import XmlRpcServer

TYPE_CHECKING = False
if TYPE_CHECKING:
    from collections.abc import Callable, Coroutine, Mapping
    from types import TracebackType
    from typing import Any, TypeVar

    from rosx.transport.server import Handler

    T = TypeVar("T")
    H = TypeVar("H", bound="Hosted")


#: Threads for the blocking name lookups asyncio makes when a URI names a host (the loop's
#: default executor, which nothing else here uses). A known name resolves in microseconds; one
#: the resolver cannot answer costs its timeout, seconds. 4 lets a few such lookups wait without
#: holding up every other connection, where Python's default would allow CPUs + 4 threads.
LOOKUP_THREADS = 4


class LoopThreadError(RuntimeError):
    """A blocking call was made on the loop's own thread, where it would wait for itself."""


class LoopThread:
    """An asyncio event loop running on its own daemon thread from `start` until `stop`."""

    def __init__(self, name: str = "rosx-loop") -> None:
        self.name = name
        self._loop: asyncio.AbstractEventLoop | None = None
        self._thread: threading.Thread | None = None
        self._ident: int | None = None
        # Tasks started by `spawn`, held until done: the loop keeps only weak references.
        self._tasks: set[asyncio.Task[Any]] = set()

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

    def start(self) -> LoopThread:
        """Start the thread and its loop (idempotent); returns self."""
        if self._loop is None:
            loop = asyncio.new_event_loop()
            loop.set_default_executor(
                concurrent.futures.ThreadPoolExecutor(
                    LOOKUP_THREADS, thread_name_prefix=f"{self.name}-lookup"
                )
            )
            ready = threading.Event()
            thread = threading.Thread(
                target=self._run, args=(loop, ready), name=self.name, daemon=True
            )
            thread.start()
            ready.wait()
            self._thread, self._ident = thread, thread.ident
            self._loop = loop
        return self

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
            loop.run_until_complete(loop.shutdown_default_executor())
            loop.close()

    def in_loop_thread(self) -> bool:
        """Whether the caller runs on the loop's thread."""
        return threading.get_ident() == self._ident

    def run(self, coro: Coroutine[Any, Any, T], timeout: float | None = None) -> T:
        """Run ``coro`` on the loop and wait for its result (or exception) in this thread.

        Raises:
            LoopThreadError: called on the loop's own thread.
            TimeoutError: ``timeout`` seconds passed; the coroutine is cancelled.
        """
        if self.in_loop_thread():
            coro.close()
            raise LoopThreadError(f"a blocking call was made on {self.name}'s own thread")
        future = asyncio.run_coroutine_threadsafe(coro, self.loop)
        try:
            return future.result(timeout)
        except concurrent.futures.TimeoutError:
            future.cancel()
            raise TimeoutError(f"the operation did not finish within {timeout} s") from None

    def submit(self, coro: Coroutine[Any, Any, T]) -> concurrent.futures.Future[T]:
        """Start ``coro`` on the loop from any thread; its future can be waited on later."""
        return asyncio.run_coroutine_threadsafe(coro, self.loop)

    def call_soon(self, callback: Callable[..., object], *args: object) -> None:
        """Run ``callback(*args)`` on the loop soon, from any thread."""
        if self.in_loop_thread():
            self.loop.call_soon(callback, *args)
        else:
            self.loop.call_soon_threadsafe(callback, *args)

    def spawn(self, coro: Coroutine[Any, Any, object]) -> None:
        """Start ``coro`` as a task on the loop, from any thread, without waiting for it."""
        self.call_soon(self._keep, coro)

    def _keep(self, coro: Coroutine[Any, Any, object]) -> None:
        task = self.loop.create_task(coro)
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)

    def stop(self, timeout: float = 5.0) -> None:
        """Stop the loop (cancelling what still runs on it) and join the thread."""
        loop, thread = self._loop, self._thread
        self._loop = self._thread = self._ident = None
        if loop is None or thread is None:
            return
        loop.call_soon_threadsafe(loop.stop)
        if thread is not threading.current_thread():
            thread.join(timeout)

    def __enter__(self) -> LoopThread:
        return self.start()

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.stop()


_lock = threading.Lock()
_process_loop: LoopThread | None = None


def process_loop() -> LoopThread:
    """The process's loop, started on first use and never stopped."""
    global _process_loop  # noqa: PLW0603 - one loop a process, created lazily
    with _lock:
        if _process_loop is None:
            _process_loop = LoopThread("rosx-io").start()
        return _process_loop


class Hosted:
    """Something with async ``start()`` and ``close()`` and a ``uri``, hosted on a loop (the
    process's unless told otherwise) for synchronous callers: the shape of `ServerThread` and
    of the master's `rosx.master.server.MasterThread`. It never stops the loop."""

    def __init__(
        self, hosted: Any, close_timeout: float, loop_thread: LoopThread | None = None
    ) -> None:
        self._hosted = hosted
        self._close_timeout = close_timeout
        self.loop_thread = loop_thread or process_loop()
        self._started = False

    @property
    def uri(self) -> str:
        """The URI it serves (after `start`)."""
        return str(self._hosted.uri)

    def start(self) -> str:
        """Start what it hosts; returns the URI.

        Raises:
            OSError: the address cannot be bound.
        """
        self.loop_thread.run(self._hosted.start())
        self._started = True
        return self.uri

    def run(self, coro: Coroutine[Any, Any, T], timeout: float | None = 10.0) -> T:
        """Run ``coro`` on the loop (to read or change the hosted object's state safely)."""
        return self.loop_thread.run(coro, timeout)

    def close(self) -> None:
        """Close what it hosts (idempotent)."""
        if self._started:
            self._started = False
            self.loop_thread.run(self._hosted.close(), timeout=self._close_timeout)

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
    """An `XmlRpcServer` on the process's loop (arguments as `XmlRpcServer`'s)."""

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
        super().__init__(self.server, close_timeout=5.0)

    @property
    def port(self) -> int:
        """The port listened on (after `start`)."""
        return self.server.port
