"""Time for nodes: ROS time (the wall clock, or ``/clock``), sleeping, and `Rate`.

A node's ROS time is its `Clock`: the wall clock, until `Clock.use_sim_time` makes it follow
``/clock`` (what a node does when ``/use_sim_time`` is set, `rosx.node.simtime`), as rospy's
and roscpp's time do. Simulated time reads 0 until the first ``/clock`` message, then each
message's time; a sleep in simulated time waits for the clock to reach its end (first for it
to leave 0), whatever the wall clock does, and raises `TimeMovedBackwardsError` when the
clock goes back meanwhile (a simulator reset, a bag played again).

Sleeping wakes early when the node shuts down: `sleep`, `Clock.sleep` and `Rate.sleep` then
raise `NodeShutdownError`, which the rospy-compatible layer turns into
``ROSInterruptException``. `Rate` keeps rospy's rhythm: each sleep ends one period after the
previous one ended, and a loop that fell more than two periods behind starts afresh instead
of rushing to catch up. On the wall clock it measures with the monotonic clock (a changed
system time does not stall it); on simulated time, with the clock.
"""

from __future__ import annotations

import threading
import time

from rosx.msg.codec.rostime import Duration, Time
from rosx.node.errors import NodeShutdownError, TimeMovedBackwardsError
from rosx.signals import wait

#: Seconds between two looks at the shutdown event while waiting for ``/clock``.
_SIM_POLL = 0.1
_ZERO = Time(0, 0)


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
    """Sleep ``duration`` seconds of wall-clock time (a float or a `Duration`; negative
    returns at once).

    Raises:
        NodeShutdownError: ``shutdown`` was set before the time was up.
    """
    seconds = _seconds(duration)
    if shutdown is None:
        if seconds > 0:
            time.sleep(seconds)
        return
    if shutdown.is_set() or (seconds > 0 and wait(shutdown, seconds)):
        raise NodeShutdownError("shutdown interrupted the sleep")


class Clock:
    """A node's ROS time: the wall clock, or simulated time from ``/clock`` (see the module
    docstring). Thread-safe: ``/clock`` arrives on one thread, sleepers wait on others."""

    def __init__(self) -> None:
        self._current: Time | None = None
        self._changed = threading.Condition()

    @property
    def is_wallclock(self) -> bool:
        """Whether this clock reads the wall clock (no `use_sim_time`)."""
        return self._current is None

    def use_sim_time(self) -> None:
        """Follow simulated time from now on: 0 until the first `set`."""
        with self._changed:
            if self._current is None:
                self._current = _ZERO
            self._changed.notify_all()

    def set(self, stamp: Time) -> None:
        """The simulated time is now ``stamp`` (a ``/clock`` message's); wakes the sleepers."""
        with self._changed:
            self._current = Time(stamp.secs, stamp.nsecs)
            self._changed.notify_all()

    def wake(self) -> None:
        """Wake the sleepers, to look at their shutdown event at once."""
        with self._changed:
            self._changed.notify_all()

    def now(self) -> Time:
        """The current ROS time."""
        current = self._current
        return now() if current is None else current

    def wait_for_valid(self, *, shutdown: threading.Event | None = None) -> bool:
        """Wait until ROS time is not 0 (roscpp's ``ros::Time::waitForValid``): at once on
        the wall clock, else until the first ``/clock``; False if ``shutdown`` came first."""
        stopped = shutdown.is_set if shutdown is not None else (lambda: False)
        with self._changed:
            while self.now() == _ZERO and not stopped():
                self._changed.wait(_SIM_POLL)
        return not stopped()

    def sleep(self, duration: float | Duration, *, shutdown: threading.Event | None = None) -> None:
        """Sleep ``duration`` seconds of ROS time (negative returns at once).

        Raises:
            NodeShutdownError: ``shutdown`` was set before the time was up.
            TimeMovedBackwardsError: simulated time went back meanwhile.
        """
        if self._current is None:
            sleep(duration, shutdown=shutdown)
            return
        seconds = _seconds(duration)
        stopped = shutdown.is_set if shutdown is not None else (lambda: False)
        with self._changed:
            start = self.now()
            while start == _ZERO and not stopped():  # no /clock yet
                self._changed.wait(_SIM_POLL)
                start = self.now()
            end = start + Duration.from_sec(max(seconds, 0.0))
            while start <= self.now() < end and not stopped():
                self._changed.wait(_SIM_POLL)
            current = self.now()
        if current < start:
            raise TimeMovedBackwardsError((start - current).to_sec())
        if stopped():
            raise NodeShutdownError("shutdown interrupted the sleep")

    def seconds(self) -> float:
        """A reading in seconds for measuring spans: monotonic on the wall clock, else the
        simulated time."""
        current = self._current
        return time.monotonic() if current is None else current.to_sec()


#: The clock of code that has no node of its own: the wall clock.
WALL = Clock()


class Rate:
    """Sleep so that a loop runs ``hz`` times a second of ``clock``'s time (rospy's ``Rate``).

    With ``reset``, a sleep during which simulated time went back starts the rhythm afresh
    instead of raising `TimeMovedBackwardsError` (rospy's ``Rate(hz, reset=True)``).
    """

    def __init__(
        self,
        hz: float,
        *,
        shutdown: threading.Event | None = None,
        clock: Clock = WALL,
        reset: bool = False,
    ) -> None:
        if hz <= 0:
            raise ValueError(f"a Rate needs a positive frequency, not {hz}")
        self.period = 1.0 / hz
        self._shutdown = shutdown
        self._clock = clock
        self._reset = reset
        self.last = clock.seconds()

    def remaining(self) -> Duration:
        """Time left in the current period (negative when the loop is late)."""
        return Duration.from_sec(self._remaining(self._clock.seconds()))

    def _remaining(self, current: float) -> float:
        self.last = min(self.last, current)
        return self.period - (current - self.last)

    def sleep(self) -> None:
        """Sleep until the end of the current period.

        Raises:
            NodeShutdownError: the node shut down meanwhile.
            TimeMovedBackwardsError: simulated time went back meanwhile (unless ``reset``).
        """
        current = self._clock.seconds()
        try:
            self._clock.sleep(self._remaining(current), shutdown=self._shutdown)
        except TimeMovedBackwardsError:
            if not self._reset:
                raise
            self.last = self._clock.seconds()
            return
        self.last += self.period
        if current - self.last > self.period * 2:
            self.last = current
