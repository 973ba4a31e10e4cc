"""The process's I/O loop: one asyncio event loop on a daemon thread, shared by every node.

Every socket of every node in the process (Slave API servers, TCPROS servers, publisher and
subscriber connections) is served by this one loop, so hosting many nodes in one process costs
no threads per node. User code never runs on it: message callbacks run on their subscriptions'
threads and service handlers on a thread pool. Synchronous callers reach the loop through
`IoLoop.run` (wait for a coroutine's result) and `IoLoop.call_soon` (fire and forget); neither
may be used from the loop's own thread, where code awaits or calls directly instead.

The thread is a daemon: a process that forgets to shut its nodes down still exits.
"""

from __future__ import annotations

import asyncio
import concurrent.futures
import threading
from typing import TYPE_CHECKING, Any, TypeVar

if TYPE_CHECKING:
    from collections.abc import Callable, Coroutine

_T = TypeVar("_T")


class LoopThreadError(RuntimeError):
    """A blocking call was made on the I/O loop's own thread, where it would deadlock."""


class IoLoop:
    """An asyncio event loop running forever on its own daemon thread."""

    def __init__(self, name: str = "rosx-io") -> None:
        self.loop = asyncio.new_event_loop()
        started = threading.Event()
        self.thread = threading.Thread(target=self._run, args=(started,), name=name, daemon=True)
        self.thread.start()
        started.wait()

    def _run(self, started: threading.Event) -> None:
        asyncio.set_event_loop(self.loop)
        self.loop.call_soon(started.set)
        self.loop.run_forever()

    def in_loop_thread(self) -> bool:
        """Whether the caller runs on the loop's thread."""
        return threading.get_ident() == self.thread.ident

    def run(self, coro: Coroutine[Any, Any, _T], timeout: float | None = None) -> _T:
        """Run ``coro`` on the loop and wait for its result (or exception) in this thread.

        Raises:
            LoopThreadError: called on the loop's thread.
            TimeoutError: ``timeout`` seconds passed; the coroutine is cancelled.
        """
        if self.in_loop_thread():
            coro.close()
            raise LoopThreadError("a blocking rosx node call was made on the I/O loop thread")
        future = asyncio.run_coroutine_threadsafe(coro, self.loop)
        try:
            return future.result(timeout)
        except concurrent.futures.TimeoutError:
            future.cancel()
            raise TimeoutError(f"the operation did not finish within {timeout} s") from None

    def submit(self, coro: Coroutine[Any, Any, _T]) -> concurrent.futures.Future[_T]:
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
        if self.in_loop_thread():
            _keep(self.loop.create_task(coro))
        else:
            self.loop.call_soon_threadsafe(lambda: _keep(self.loop.create_task(coro)))


# Tasks are held until done: the loop keeps only weak references to them.
_tasks: set[asyncio.Task[Any]] = set()


def _keep(task: asyncio.Task[Any]) -> None:
    _tasks.add(task)
    task.add_done_callback(_tasks.discard)


_lock = threading.Lock()
_shared: IoLoop | None = None


def io_loop() -> IoLoop:
    """The process-wide loop, started on first use."""
    global _shared  # noqa: PLW0603 - one loop a process, created lazily
    with _lock:
        if _shared is None:
            _shared = IoLoop()
        return _shared
