"""Time for nodes: the wall clock as ROS `Time`, sleeping, and `Rate` (rospy's ``rospy.timer``).

rosx nodes run on wall-clock time (``/use_sim_time`` is not followed). Sleeping wakes early
when the node shuts down: `sleep` and `Rate.sleep` then raise `NodeShutdownError`, which the
rospy-compatible layer turns into ``ROSInterruptException``. `Rate` keeps rospy's rhythm: each
sleep ends one period after the previous one ended, and a loop that fell more than two periods
behind starts afresh instead of rushing to catch up.
"""

from __future__ import annotations

import threading
import time
from typing import TYPE_CHECKING

from rosx.msg.codec.rostime import Duration, Time
from rosx.node.errors import NodeShutdownError

if TYPE_CHECKING:
    from collections.abc import Callable


def now() -> Time:
    """The current wall-clock time as a ROS `Time`."""
    nanos = time.time_ns()
    return Time(nanos // 1_000_000_000, nanos % 1_000_000_000)


def _seconds(duration: float | Duration) -> float:
    return duration.to_sec() if isinstance(duration, Duration) else float(duration)


def sleep(
    duration: float | Duration,
    *,
    shutdown: threading.Event | None = None,
) -> None:
    """Sleep ``duration`` seconds (a float or a `Duration`; negative returns at once).

    Raises:
        NodeShutdownError: ``shutdown`` was set before the time was up.
    """
    seconds = _seconds(duration)
    if shutdown is None:
        if seconds > 0:
            time.sleep(seconds)
        return
    if shutdown.is_set() or (seconds > 0 and shutdown.wait(seconds)):
        raise NodeShutdownError("shutdown interrupted the sleep")


class Rate:
    """Sleep so that a loop runs ``hz`` times a second (rospy's ``Rate``)."""

    def __init__(
        self,
        hz: float,
        *,
        shutdown: threading.Event | None = None,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        if hz <= 0:
            raise ValueError(f"a Rate needs a positive frequency, not {hz}")
        self.period = 1.0 / hz
        self._shutdown = shutdown
        self._clock = clock
        self.last = clock()

    def remaining(self) -> Duration:
        """Time left in the current period (negative when the loop is late)."""
        return Duration.from_sec(self._remaining(self._clock()))

    def _remaining(self, current: float) -> float:
        self.last = min(self.last, current)
        return self.period - (current - self.last)

    def sleep(self) -> None:
        """Sleep until the end of the current period.

        Raises:
            NodeShutdownError: the node shut down meanwhile.
        """
        current = self._clock()
        sleep(self._remaining(current), shutdown=self._shutdown)
        self.last += self.period
        if current - self.last > self.period * 2:
            self.last = current
