"""Time for rospy-style nodes: `Time`, `Duration`, `get_rostime`, `sleep`, `Rate` and `Timer`.

The node runs on wall-clock time. As in rospy, reading ROS time (``Time.now()``,
`get_rostime`, creating a `Rate`) needs `init_node` first and otherwise raises
``time is not initialized. Have you called init_node()?``. Sleeps end early when the node
shuts down and then raise `ROSInterruptException` (``ROS shutdown request``), so that a loop
``while not rospy.is_shutdown(): …; rate.sleep()`` ends promptly on Ctrl-C.
"""

from __future__ import annotations

import threading
import time
from typing import TYPE_CHECKING

from rosx.client import state
from rosx.client.exceptions import ROSInitException, ROSInterruptException
from rosx.msg.codec import rostime
from rosx.node.clock import Rate as _NodeRate
from rosx.node.clock import sleep as _node_sleep
from rosx.node.errors import NodeShutdownError

if TYPE_CHECKING:
    from collections.abc import Callable


class Time(rostime.Time):
    """A point in ROS time; ``Time.now()`` reads the node's clock."""

    __slots__ = ()

    @staticmethod
    def now() -> Time:
        """The current ROS time."""
        return get_rostime()

    @classmethod
    def from_seconds(cls, float_secs: float) -> Time:
        """The time ``float_secs`` seconds after the epoch (rospy's older name of from_sec)."""
        return cls.from_sec(float_secs)

    def __repr__(self) -> str:
        return f"rospy.Time[{self.to_nsec()}]"


class Duration(rostime.Duration):
    """A span of ROS time."""

    __slots__ = ()

    @classmethod
    def from_seconds(cls, float_secs: float) -> Duration:
        """The duration of ``float_secs`` seconds (rospy's older name of from_sec)."""
        return cls.from_sec(float_secs)

    def __repr__(self) -> str:
        return f"rospy.Duration[{self.to_nsec()}]"


def _check_time() -> None:
    if not state.CLIENT.initialized:
        raise ROSInitException("time is not initialized. Have you called init_node()?")


def get_rostime() -> Time:
    """The current ROS time as a `Time`.

    Raises:
        ROSInitException: `init_node` has not been called.
    """
    _check_time()
    nanos = time.time_ns()
    return Time(nanos // 1_000_000_000, nanos % 1_000_000_000)


def get_time() -> float:
    """The current ROS time in float seconds, as ``time.time()`` gives them."""
    return get_rostime().to_sec()


def sleep(duration: float | rostime.Duration) -> None:
    """Sleep ``duration`` seconds (a float or a `Duration`); a negative duration returns at once.

    Raises:
        ROSInterruptException: the node shut down before the time was up.
    """
    try:
        _node_sleep(duration, shutdown=state.CLIENT.shutdown_event)
    except NodeShutdownError:
        raise ROSInterruptException("ROS shutdown request") from None


class Rate:
    """Sleep so that a loop runs ``hz`` times a second, accounting for the loop's own work."""

    def __init__(self, hz: float, reset: bool = False) -> None:
        _check_time()
        self._rate = _NodeRate(hz, shutdown=state.CLIENT.shutdown_event)
        self.sleep_dur = Duration(0, int(1e9 / hz))
        self._reset = reset

    def remaining(self) -> Duration:
        """Time left in the current period (negative when the loop runs late)."""
        left = self._rate.remaining()
        return Duration(left.secs, left.nsecs)

    def sleep(self) -> None:
        """Sleep until the end of the current period.

        Raises:
            ROSInterruptException: the node shut down meanwhile.
        """
        try:
            self._rate.sleep()
        except NodeShutdownError:
            raise ROSInterruptException("ROS shutdown request") from None


class TimerEvent:
    """What a `Timer` callback receives: when it was due and when it ran."""

    def __init__(
        self,
        last_expected: Time | None,
        last_real: Time | None,
        current_expected: Time,
        current_real: Time,
        last_duration: float | None,
    ) -> None:
        self.last_expected = last_expected
        self.last_real = last_real
        self.current_expected = current_expected
        self.current_real = current_real
        self.last_duration = last_duration


class Timer(threading.Thread):
    """Calls ``callback(TimerEvent)`` every ``period`` on a thread of its own until shutdown."""

    def __init__(
        self,
        period: rostime.Duration,
        callback: Callable[[TimerEvent], object],
        oneshot: bool = False,
        reset: bool = False,
    ) -> None:
        super().__init__(name="rosx-timer", daemon=True)
        self._period = period
        self._callback = callback
        self._oneshot = oneshot
        self._reset = reset
        self._halt = threading.Event()
        self.start()

    def shutdown(self) -> None:
        """Stop calling the callback."""
        self._halt.set()

    def run(self) -> None:
        rate = Rate(1.0 / self._period.to_sec(), reset=self._reset)
        current_expected = get_rostime() + self._period
        last_expected: Time | None = None
        last_real: Time | None = None
        last_duration: float | None = None
        while not self._halt.is_set() and not state.CLIENT.is_shutdown():
            try:
                rate.sleep()
            except ROSInterruptException:
                break
            if self._halt.is_set():
                break
            current_real = get_rostime()
            started = time.monotonic()
            self._callback(
                TimerEvent(last_expected, last_real, current_expected, current_real, last_duration)
            )
            if self._oneshot:
                break
            last_duration = time.monotonic() - started
            last_expected, last_real = current_expected, current_real
            current_expected = current_expected + self._period


__all__ = [
    "Duration",
    "Rate",
    "Time",
    "Timer",
    "TimerEvent",
    "get_rostime",
    "get_time",
    "sleep",
]
