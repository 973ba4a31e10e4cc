"""`Ticker`: a thread that calls a function every period, like turtlesim's 16 ms Qt timer.

Ticks are scheduled on the monotonic clock, one period after the previous one was due, so
they do not drift. A tick that runs late is not made up for by a burst: when the thread falls
more than a period behind it starts afresh from now (the simulation then simply runs slower,
as turtlesim does under load, its step being fixed). An exception in the function is reported
through ``on_error`` and the ticking goes on.
"""

from __future__ import annotations

import threading
import time
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Callable


class Ticker:
    """Calls ``tick()`` every ``period`` seconds on a thread of its own, until `stop`."""

    def __init__(
        self,
        period: float,
        tick: Callable[[], None],
        *,
        name: str = "rosx-ticker",
        on_error: Callable[[BaseException], None] | None = None,
    ) -> None:
        self.period = period
        self._tick = tick
        self._on_error = on_error
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name=name, daemon=True)

    def start(self) -> None:
        """Start ticking (the first tick comes one period from now)."""
        self._thread.start()

    def stop(self, timeout: float = 5.0) -> None:
        """Stop ticking and wait for a tick in progress (unless called from a tick)."""
        self._stop.set()
        if self._thread.is_alive() and threading.current_thread() is not self._thread:
            self._thread.join(timeout)

    @property
    def running(self) -> bool:
        """Whether the thread is ticking."""
        return self._thread.is_alive() and not self._stop.is_set()

    def _run(self) -> None:
        due = time.monotonic() + self.period
        while not self._stop.wait(max(0.0, due - time.monotonic())):
            try:
                self._tick()
            except Exception as exc:  # one bad tick must not stop the simulation
                if self._on_error is not None:
                    self._on_error(exc)
            due += self.period
            now = time.monotonic()
            if now - due > self.period:
                due = now
