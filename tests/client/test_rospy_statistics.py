"""Topic statistics: ``/enable_statistics`` makes subscriptions report on ``/statistics``."""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator
from types import ModuleType
from typing import Any

import pytest

from rosx.master.client import MasterClient
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node, local
from rosx.node.stats import StatisticsWindow, WindowSettings
from tests.support.procs import wait_for

String = get_message_class("std_msgs/String")
Header = get_message_class("std_msgs/Header")
TopicStatistics = get_message_class("rosgraph_msgs/TopicStatistics")
MS = 1_000_000
S = 1_000_000_000
T = 1_700_000_000 * S  # a time of day, as the clock gives it


# -- the window ------------------------------------------------------------------------------


def test_the_first_message_closes_a_window_of_one() -> None:
    window = StatisticsWindow(WindowSettings(), window_start=5 * S)
    report = window.arrived(6 * S, total_bytes=20)
    assert report is not None
    assert (report.window_start, report.window_stop) == (5 * S, 6 * S)
    assert (report.delivered_msgs, report.traffic, report.period_mean) == (1, 20, 0)


def test_a_window_reports_gaps_ages_drops_and_bytes() -> None:
    window = StatisticsWindow(WindowSettings(min_elements=1), window_start=0)
    window.arrived(10 * S, 10, stamp=10 * S, seq=1)  # closes the first window
    # Gaps of 200 and 300 ms; seq 3 is missing; stamps 50, 50 and 200 ms old.
    assert window.arrived(10 * S + 700 * MS, 20, stamp=10 * S + 650 * MS, seq=2) is None
    assert window.arrived(10 * S + 900 * MS, 30, stamp=10 * S + 850 * MS, seq=4) is None
    report = window.arrived(11 * S + 200 * MS, 45, stamp=11 * S, seq=5)
    assert report is not None
    assert (report.window_start, report.window_stop) == (10 * S, 11 * S + 200 * MS)
    assert (report.delivered_msgs, report.dropped_msgs, report.traffic) == (3, 1, 35)
    assert (report.period_mean, report.period_stddev, report.period_max) == (
        250 * MS,
        50 * MS,
        300 * MS,
    )
    assert (report.stamp_age_mean, report.stamp_age_max) == (100 * MS, 200 * MS)


def test_the_report_period_follows_the_message_count() -> None:
    settings = WindowSettings(min_elements=3, max_elements=5, min_window=0.5, max_window=4.0)
    window = StatisticsWindow(settings, window_start=T)
    window.arrived(T + 1 * S, 0)  # one message: the period doubles to 2 s
    assert window.arrived(T + 2 * S, 0) is None
    assert window.arrived(T + 3 * S + 1, 0) is not None  # two messages: 4 s
    assert window.arrived(T + 7 * S, 0) is None
    assert window.arrived(T + 7 * S + 2, 0) is not None  # two again: the period stays at 4 s
    for i in range(6):
        assert window.arrived(T + 8 * S + i, 0) is None
    assert window.arrived(T + 11 * S + 3, 0) is not None  # seven messages: back to 2 s
    assert window.arrived(T + 13 * S + 3, 0) is None
    assert window.arrived(T + 13 * S + 4, 0) is not None


# -- a node ----------------------------------------------------------------------------------


@pytest.fixture
def statistics_params(master: str) -> Iterator[MasterClient]:
    client = MasterClient(master, "/statistics_test")
    client.call("setParam", "/enable_statistics", True)
    client.call("setParam", "/statistics_window_min_elements", 2)
    yield client
    for name in ("/enable_statistics", "/statistics_window_min_elements"):
        client.call("deleteParam", name)


def _publish_until(pub: Any, done: threading.Event, make: Callable[[int], Any]) -> None:
    seq = 0
    while not done.wait(0.02):
        seq += 1
        pub.publish(make(seq))


def test_subscriptions_report_on_statistics(
    rospy: ModuleType,
    make_node: Callable[[str], Node],
    statistics_params: MasterClient,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(local, "ENABLED", False)  # over TCPROS, as between processes
    rospy.init_node("measured", disable_signals=True)
    talker = make_node("talker")
    reports: list[Any] = []
    watcher = make_node("watcher")
    watcher.subscribe("/statistics", TopicStatistics, reports.append)
    got: list[Any] = []
    sub = rospy.Subscriber("/chatter", String, got.append)
    pub = talker.advertise("/chatter", String, queue_size=10)
    wait_for(lambda: sub.get_num_connections() == 1, what="the connection")
    done = threading.Event()
    thread = threading.Thread(
        target=_publish_until, args=(pub, done, lambda i: String(data=f"hello {i}"))
    )
    thread.start()
    try:
        wait_for(lambda: any(r.delivered_msgs > 1 for r in reports), what="a report")
    finally:
        done.set()
        thread.join()
    report = next(r for r in reports if r.delivered_msgs > 1)
    assert (report.topic, report.node_pub, report.node_sub) == ("/chatter", "/talker", "/measured")
    assert report.window_stop > report.window_start
    assert report.traffic > 0 and report.dropped_msgs == 0
    assert report.period_mean.to_nsec() > 0 and report.stamp_age_max.to_nsec() == 0
    assert got  # the subscriber's own callback still gets every message

    def subscribers(topic: str) -> list[str]:
        state = statistics_params.call("getSystemState")
        return next((nodes for name, nodes in state[1] if name == topic), [])

    assert subscribers("/chatter") == ["/measured"]
    sub.unregister()  # statistics do not keep the topic subscribed
    wait_for(lambda: subscribers("/chatter") == [], what="the subscription to go")


def test_no_statistics_unless_enabled(
    rospy: ModuleType, make_node: Callable[[str], Node], master: str
) -> None:
    rospy.init_node("unmeasured", disable_signals=True)
    talker = make_node("talker2")
    got: list[Any] = []
    rospy.Subscriber("/quiet", String, got.append)
    pub = talker.advertise("/quiet", String, queue_size=10)
    wait_for(lambda: pub.get_num_connections() == 1, what="the connection")
    for i in range(3):
        pub.publish(String(data=str(i)))
    wait_for(lambda: len(got) == 3, what="three messages")
    state = MasterClient(master, "/check").call("getSystemState")
    assert "/statistics" not in [name for name, _ in state[0]]
