"""Time for rospy-style nodes: `Time`, `Duration`, `get_rostime`, `sleep`, `Rate` and `Timer`.

ROS time is the node's clock (`rosx.node.clock.Clock`): the wall clock, or, when
``/use_sim_time`` is set as `init_node` starts the node, ``/clock`` (0 until its first message),
as in rospy: ``Time.now()``, `sleep`, `Rate` and `Timer` then follow the simulator, however fast
it runs. As in rospy, reading ROS time (``Time.now()``, `get_rostime`, creating a `Rate`) needs
`init_node` first and otherwise raises ``time is not initialized. Have you called
init_node()?``; a sleep before it sleeps on the wall clock. Sleeps end early when the node
shuts down and then raise `ROSInterruptException` (``ROS shutdown request``), so that a loop
``while not rospy.is_shutdown(): …; rate.sleep()`` ends promptly on Ctrl-C; a sleep during
which simulated time goes back raises `ROSTimeMovedBackwardsException` (a `Rate` made with
``reset=True`` starts its rhythm afresh instead).
"""

from __future__ import annotations

import threading
import time
from typing import TYPE_CHECKING

from rosx.client import state
from rosx.client.exceptions import (
    ROSInitException,
    ROSInterruptException,
    ROSTimeMovedBackwardsException,
)
from rosx.msg.codec import rostime
from rosx.node.clock import WALL, Clock
from rosx.node.clock import Rate as _NodeRate
from rosx.node.errors import NodeShutdownError, TimeMovedBackwardsError

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


def _clock() -> Clock:
    """The node's clock; the wall clock before `init_node`."""
    node = state.CLIENT.node
    return WALL if node is None else node.clock


def get_rostime() -> Time:
    """The current ROS time as a `Time`.

    Raises:
        ROSInitException: `init_node` has not been called.
    """
    _check_time()
    current = _clock().now()
    return Time(current.secs, current.nsecs)


def is_wallclock() -> bool:
    """Whether ROS time is the wall clock (no ``/use_sim_time``), as rospy's
    ``rospy.rostime.is_wallclock``."""
    return _clock().is_wallclock


def wallsleep(duration: float) -> None:
    """Sleep ``duration`` seconds of wall-clock time, whatever ROS time does."""
    time.sleep(duration)


def get_time() -> float:
    """The current ROS time in float seconds, as ``time.time()`` gives them."""
    return get_rostime().to_sec()


def sleep(duration: float | rostime.Duration) -> None:
    """Sleep ``duration`` seconds (a float or a `Duration`); a negative duration returns at once.

    Raises:
        ROSInterruptException: the node shut down before the time was up.
        ROSTimeMovedBackwardsException: simulated time went back meanwhile.
    """
    try:
        _clock().sleep(duration, shutdown=state.CLIENT.shutdown_event)
    except NodeShutdownError:
        raise ROSInterruptException("ROS shutdown request") from None
    except TimeMovedBackwardsError as moved:
        raise ROSTimeMovedBackwardsException(moved.jump) from None


class Rate:
    """Sleep so that a loop runs ``hz`` times a second, accounting for the loop's own work."""

    def __init__(self, hz: float, reset: bool = False) -> None:
        _check_time()
        self._rate = _NodeRate(
            hz, shutdown=state.CLIENT.shutdown_event, clock=_clock(), reset=reset
        )
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
            ROSTimeMovedBackwardsException: simulated time went back meanwhile (unless the
                rate was made with ``reset``).
        """
        try:
            self._rate.sleep()
        except NodeShutdownError:
            raise ROSInterruptException("ROS shutdown request") from None
        except TimeMovedBackwardsError as moved:
            raise ROSTimeMovedBackwardsException(moved.jump) from None


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
        """The timer's thread: sleep to each expected time on ROS time, then call the callback
        with a `TimerEvent`, until `shutdown`, the node's shutdown, or the first call of a
        one-shot timer. A jump back in simulated time ends the timer with
        `ROSInterruptException`, as in rospy."""
        rate = Rate(1.0 / self._period.to_sec(), reset=self._reset)
        current_expected = get_rostime() + self._period
        last_expected: Time | None = None
        last_real: Time | None = None
        last_duration: float | None = None
        while not self._halt.is_set() and not state.CLIENT.is_shutdown():
            try:
                rate.sleep()
            except ROSTimeMovedBackwardsException:
                if state.CLIENT.is_shutdown() or self._halt.is_set():
                    break
                raise  # simulated time went back: the timer ends, as rospy's
            except ROSInterruptException:
                # The node the timer sleeps on shut down: the timer ends quietly, even where
                # the client already names another node (a process that starts a second one).
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
    "is_wallclock",
    "sleep",
    "wallsleep",
]
