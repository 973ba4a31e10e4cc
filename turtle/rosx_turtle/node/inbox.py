"""`Inbox`: work for the tick thread, run between ticks (roscpp's callback queue + spinOnce).

turtlesim runs every subscription and service callback on its timer thread, in
``ros::spinOnce()`` at the start of each tick, so callbacks never race the simulation. Here the
receiver and service threads `post` (fire and forget) or `call` (wait for the result) and the
tick thread `drain`s. Once `close`d, pending and later calls fail with `InboxClosedError`.
"""

from __future__ import annotations

import contextlib
import queue
import threading
from concurrent.futures import Future
from typing import TYPE_CHECKING, Generic, TypeVar

if TYPE_CHECKING:
    from collections.abc import Callable

T = TypeVar("T")
S = TypeVar("S")


class InboxClosedError(RuntimeError):
    """The simulator stopped before it could run the request."""


class Inbox(Generic[S]):
    """Actions taking the subject ``S`` (the simulation), run by whoever calls `drain`."""

    def __init__(self) -> None:
        self._queue: queue.SimpleQueue[tuple[Callable[[S], object], Future[object] | None]] = (
            queue.SimpleQueue()
        )
        self._lock = threading.Lock()
        self._closed = False

    def post(self, action: Callable[[S], object]) -> None:
        """Queue ``action``; its result and errors are dropped."""
        with self._lock:
            if not self._closed:
                self._queue.put((action, None))

    def call(self, action: Callable[[S], T], timeout: float | None = None) -> T:
        """Queue ``action`` and wait for its result (its exception is raised here).

        Raises:
            InboxClosedError: the inbox closed before the action ran.
        """
        future: Future[T] = Future()
        with self._lock:
            if self._closed:
                raise InboxClosedError("the simulator is shutting down")
            self._queue.put((action, future))  # type: ignore[arg-type]
        return future.result(timeout)

    def drain(self, subject: S) -> None:
        """Run every queued action, in order."""
        while True:
            try:
                action, future = self._queue.get_nowait()
            except queue.Empty:
                return
            if future is None:
                with contextlib.suppress(Exception):  # nobody waits for a posted action
                    action(subject)
            elif future.set_running_or_notify_cancel():
                try:
                    future.set_result(action(subject))
                except Exception as exc:
                    future.set_exception(exc)

    def close(self) -> None:
        """Refuse new work and fail what is still queued."""
        with self._lock:
            self._closed = True
        while True:
            try:
                _, future = self._queue.get_nowait()
            except queue.Empty:
                return
            if future is not None and future.set_running_or_notify_cancel():
                future.set_exception(InboxClosedError("the simulator is shutting down"))
