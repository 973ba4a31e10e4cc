"""Simulated time in the rospy API, as Debian's rospy keeps it: with ``/use_sim_time`` set
when the node starts, ROS time is 0 until the first ``/clock`` message and then each message's
time; ``sleep``, ``Rate`` and ``Timer`` wait for ``/clock``, not the wall clock; time going back
ends a sleep with ``ROSTimeMovedBackwardsException``; ``/rosout`` records carry the time."""

from __future__ import annotations

import re
import sys
import threading
from collections.abc import Callable, Iterator
from types import ModuleType
from typing import Any

import pytest

from rosx.client.timing import is_wallclock
from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.rostime import Time
from rosx.node import Node
from tests.support.procs import wait_for

ClockMessage = get_message_class("rosgraph_msgs/Clock")
Log = get_message_class("rosgraph_msgs/Log")


class Simulator:
    """A node publishing ``/clock``, the way stageros or ``rosbag play --clock`` does."""

    def __init__(self, node: Node) -> None:
        self.publisher = node.advertise("/clock", ClockMessage, queue_size=10)

    def wait_for(self, rospy: ModuleType) -> None:
        wait_for(lambda: self.publisher.get_num_connections() > 0, what="rospy on /clock")

    def at(self, seconds: float, rospy: ModuleType) -> None:
        """Publish ``seconds`` on /clock and wait until rospy's time reads it."""
        self.publisher.publish(ClockMessage(clock=Time.from_sec(seconds)))
        wait_for(lambda: rospy.get_time() == pytest.approx(seconds), what=f"time {seconds}")


@pytest.fixture
def simulator(
    rospy: ModuleType, make_node: Callable[[str], Node]
) -> Iterator[Callable[[], Simulator]]:
    """``/use_sim_time`` set, then (once called, after ``init_node``) a ``/clock`` publisher
    that rospy listens to."""
    clock_node = make_node("/simulator")
    clock_node.params.set("/use_sim_time", True)

    def make() -> Simulator:
        made = Simulator(clock_node)
        made.wait_for(rospy)
        return made

    yield make
    clock_node.params.delete("/use_sim_time")  # the master is the module's


class Sleeper:
    """``call()`` on a thread of its own: whether it has returned, and what it raised. Made,
    it returns once the call waits (its thread blocked in a condition's wait), so the clock
    the test then moves is the one the sleep started from."""

    def __init__(self, call: Callable[[], object]) -> None:
        self.done = threading.Event()
        self.raised: BaseException | None = None

        def run() -> None:
            try:
                call()
            except BaseException as error:  # kept for the test to look at
                self.raised = error
            self.done.set()

        self.thread = threading.Thread(target=run, daemon=True)
        self.thread.start()
        wait_for(lambda: self.done.is_set() or _waiting(self.thread), what="the sleep to begin")

    def started_from(self) -> Any:
        """The ROS time the sleep counts from (the clock's ``sleep``'s ``start``), once it
        has seen one that is not 0; None before."""
        frame = sys._current_frames().get(self.thread.ident or 0)
        while frame is not None:
            start = frame.f_locals.get("start") if frame.f_code.co_name == "sleep" else None
            if start is not None and not start.is_zero():
                return start
            frame = frame.f_back
        return None


def _waiting(thread: threading.Thread) -> bool:
    frame = sys._current_frames().get(thread.ident or 0)
    return frame is not None and frame.f_code.co_name == "wait"


def test_time_is_zero_until_the_first_clock_then_each_clocks(
    rospy: ModuleType, simulator: Callable[[], Simulator]
) -> None:
    rospy.init_node("timed", disable_signals=True)
    assert rospy.get_rostime() == rospy.Time(0, 0)
    assert (rospy.Time.now().to_sec(), rospy.get_time()) == (0.0, 0.0)
    assert not is_wallclock()
    clock = simulator()
    clock.at(5.0, rospy)
    assert rospy.Time.now() == rospy.Time(5, 0)
    clock.at(7.25, rospy)
    assert isinstance(rospy.get_rostime(), rospy.Time)


def test_sleep_and_rate_last_simulated_seconds(
    rospy: ModuleType, simulator: Callable[[], Simulator]
) -> None:
    rospy.init_node("sleeper", disable_signals=True)
    clock = simulator()
    clock.at(10.0, rospy)
    sleeper = Sleeper(lambda: rospy.sleep(2.0))
    clock.at(11.9, rospy)
    assert not sleeper.done.is_set()  # 1.9 simulated seconds: still asleep
    clock.at(12.0, rospy)
    assert sleeper.done.wait(10) and sleeper.raised is None
    rate = rospy.Rate(2.0)  # half a simulated second
    sleeper = Sleeper(rate.sleep)
    clock.at(12.4, rospy)
    assert not sleeper.done.is_set()
    clock.at(12.5, rospy)
    assert sleeper.done.wait(10) and sleeper.raised is None


def test_a_sleep_waits_for_the_first_clock(
    rospy: ModuleType, simulator: Callable[[], Simulator]
) -> None:
    rospy.init_node("early", disable_signals=True)
    sleeper = Sleeper(lambda: rospy.sleep(1.0))
    clock = simulator()
    clock.at(3.0, rospy)  # the sleep counts from the first time it sees, not from 0
    # On a loaded machine the sleeper's thread may be scheduled late: once it has seen 3.0.
    wait_for(lambda: sleeper.started_from() is not None, what="the sleep to see 3.0")
    assert sleeper.started_from().to_sec() == 3.0
    clock.at(3.5, rospy)
    assert not sleeper.done.is_set()
    clock.at(5.0, rospy)
    assert sleeper.done.wait(10) and sleeper.raised is None


def test_time_going_back_ends_a_sleep_as_rospy_says(
    rospy: ModuleType, simulator: Callable[[], Simulator]
) -> None:
    rospy.init_node("reset", disable_signals=True)
    clock = simulator()
    clock.at(50.0, rospy)
    sleeper = Sleeper(lambda: rospy.sleep(100.0))
    clock.at(20.0, rospy)
    assert sleeper.done.wait(10)
    assert isinstance(sleeper.raised, rospy.ROSTimeMovedBackwardsException)
    assert isinstance(sleeper.raised, rospy.ROSInterruptException)
    assert str(sleeper.raised) == "ROS time moved backwards"
    rate = rospy.Rate(1.0, reset=True)  # a rate with reset starts afresh instead
    sleeper = Sleeper(rate.sleep)
    clock.at(10.0, rospy)
    assert sleeper.done.wait(10) and sleeper.raised is None


def test_timer_events_follow_simulated_time(
    rospy: ModuleType, simulator: Callable[[], Simulator]
) -> None:
    rospy.init_node("ticker", disable_signals=True)
    clock = simulator()
    clock.at(100.0, rospy)
    events: list[Any] = []
    timer = rospy.Timer(rospy.Duration(1), events.append)
    for tenth in range(1, 36):
        clock.at(100.0 + tenth / 10, rospy)
    wait_for(lambda: len(events) >= 3, what="three timer events")
    timer.shutdown()
    expected = [event.current_expected.to_sec() for event in events[:3]]
    assert expected == pytest.approx([101.0, 102.0, 103.0])
    assert all(100.9 < event.current_real.to_sec() < 103.6 for event in events[:3])


def test_rosout_records_carry_simulated_time(
    rospy: ModuleType, simulator: Callable[[], Simulator], make_node: Callable[[str], Node]
) -> None:
    rospy.init_node("logger", disable_signals=True)
    clock = simulator()
    clock.at(42.5, rospy)
    records: list[Any] = []
    make_node("/listener").subscribe("/rosout", Log, records.append, queue_size=10)
    wait_for(lambda: rospy.get_param("/use_sim_time"), what="the parameter")

    def logged() -> bool:
        rospy.loginfo("at 42.5")
        return any(record.msg == "at 42.5" for record in records)

    wait_for(logged, what="the record on /rosout")
    record = next(record for record in records if record.msg == "at 42.5")
    assert record.header.stamp.to_sec() == pytest.approx(42.5)


def test_console_lines_show_the_wall_clock_then_simulated_time(
    rospy: ModuleType, simulator: Callable[[], Simulator], capsys: pytest.CaptureFixture[str]
) -> None:
    """rospy's ``${time}`` under ``/use_sim_time``: ``[INFO] [<wall>, <simulated>]: ...``."""
    rospy.init_node("talker_on_sim_time", disable_signals=True)
    clock = simulator()
    clock.at(42.5, rospy)
    capsys.readouterr()
    rospy.loginfo("at 42.5")
    line = capsys.readouterr().out
    found = re.fullmatch(r"\[INFO\] \[(\d+\.\d{6}), (\d+\.\d{6})\]: at 42\.5\n", line)
    assert found, line
    assert float(found[1]) > 1e9  # the wall clock's
    assert found[2] == "42.500000"


def test_disable_rostime_keeps_the_wall_clock(
    rospy: ModuleType, simulator: Callable[[], Simulator]
) -> None:
    rospy.init_node("walled", disable_signals=True, disable_rostime=True)
    assert is_wallclock()
    assert rospy.get_time() > 1e9
