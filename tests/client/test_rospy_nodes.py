"""The rospy-compatible API's node: init_node, names, command lines, time, shutdown."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from types import ModuleType
from typing import Any

import pytest

from rosx.client import state
from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.procs import wait_for

String = get_message_class("std_msgs/String")


def test_init_node_registers_the_node_and_names_it(rospy: ModuleType, master: str) -> None:
    assert rospy.get_name() == "/unnamed"
    rospy.init_node("talker", disable_signals=True)
    assert rospy.get_name() == "/talker"
    assert rospy.get_namespace() == "/"
    assert rospy.get_node_uri().startswith("http://")
    assert "/talker" in _nodes(rospy)
    assert rospy.resolve_name("chatter") == "/chatter"
    assert rospy.resolve_name("~private") == "/talker/private"


def test_init_node_refuses_what_rospy_refuses(rospy: ModuleType) -> None:
    with pytest.raises(ValueError, match=r"^name must not be empty$"):
        rospy.init_node("")
    with pytest.raises(ValueError, match=r"^namespaces are not allowed in node names$"):
        rospy.init_node("a/b")
    rospy.init_node("once", disable_signals=True)
    rospy.init_node("once", disable_signals=True)  # the same arguments: allowed
    with pytest.raises(rospy.ROSException, match="has already been called with different"):
        rospy.init_node("twice", disable_signals=True)


def test_anonymous_nodes_get_rospys_unique_names(rospy: ModuleType) -> None:
    rospy.init_node("listener", anonymous=True, disable_signals=True)
    base, pid, millis = rospy.get_name().rsplit("_", 2)
    assert base == "/listener" and pid.isdigit() and millis.isdigit()


def test_the_command_line_names_remaps_and_sets_parameters(rospy: ModuleType) -> None:
    argv = ["script.py", "__name:=renamed", "__ns:=/robot", "chatter:=talk", "_rate:=5", "x"]
    rospy.init_node("original", argv=argv, anonymous=True, disable_signals=True)
    assert rospy.get_name() == "/robot/renamed"
    assert rospy.get_namespace() == "/robot/"
    assert rospy.get_param("~rate") == 5
    assert rospy.get_param("/robot/renamed/rate") == 5
    pub = rospy.Publisher("chatter", String, queue_size=1)
    assert pub.resolved_name == "/robot/talk"
    assert rospy.myargv(argv) == ["script.py", "x"]


def test_a_bad_private_parameter_stops_init_node(rospy: ModuleType) -> None:
    with pytest.raises(rospy.ROSInitException, match="invalid command-line parameters"):
        rospy.init_node("n", argv=["s", "_bad:=[1, "], disable_signals=True)


def test_time_needs_init_node_as_in_rospy(rospy: ModuleType) -> None:
    text = "^time is not initialized. Have you called init_node\\(\\)\\?$"
    with pytest.raises(rospy.ROSInitException, match=text):
        rospy.Rate(10)
    with pytest.raises(rospy.ROSInitException, match=text):
        rospy.Time.now()
    rospy.sleep(0.001)  # wall-clock sleeping needs no node
    rospy.init_node("clock", disable_signals=True)
    now = rospy.Time.now()
    assert abs(now.to_sec() - time.time()) < 1.0
    assert abs(rospy.get_time() - time.time()) < 1.0
    assert repr(rospy.Duration(1)) == "rospy.Duration[1000000000]"


def test_rate_keeps_the_loop_at_its_frequency(rospy: ModuleType) -> None:
    rospy.init_node("looper", disable_signals=True)
    rate = rospy.Rate(50)
    start = time.monotonic()
    for _ in range(10):
        rate.sleep()
    assert 0.15 < time.monotonic() - start < 0.5


def test_shutdown_runs_hooks_then_wakes_sleepers(rospy: ModuleType) -> None:
    rospy.init_node("sleeper", disable_signals=True)
    events: list[str] = []
    rospy.on_shutdown(lambda: events.append(f"hook, shut down: {rospy.is_shutdown()}"))
    rate = rospy.Rate(0.1)
    timer = threading.Timer(0.2, rospy.signal_shutdown, args=("done",))
    timer.start()
    start = time.monotonic()
    with pytest.raises(rospy.ROSInterruptException, match=r"^ROS shutdown request$"):
        rate.sleep()
    assert time.monotonic() - start < 5
    assert rospy.is_shutdown()
    assert events == ["hook, shut down: False"]
    with pytest.raises(rospy.ROSInterruptException):
        rospy.sleep(10)
    wait_for(lambda: "/sleeper" not in _nodes(rospy), what="the node to unregister")


def test_interrupt_exception_is_also_a_keyboard_interrupt(rospy: ModuleType) -> None:
    assert issubclass(rospy.ROSInterruptException, KeyboardInterrupt)
    assert issubclass(rospy.ROSInterruptException, rospy.ROSException)


def test_rosnode_kill_shuts_the_node_down(
    rospy: ModuleType, make_node: Callable[[str], Node]
) -> None:
    rospy.init_node("victim", disable_signals=True)
    killer = make_node("killer")
    uri = killer.master.call("lookupNode", "/victim")
    from rosx.transport.client import XmlRpcClient

    with XmlRpcClient(timeout=5.0) as client:
        client.call(uri, "shutdown", "/killer", "rosnode kill")
    wait_for(rospy.is_shutdown, what="the shutdown")


def test_spin_needs_a_node_and_returns_on_shutdown(rospy: ModuleType) -> None:
    with pytest.raises(rospy.ROSInitException, match=r"must call rospy.init_node\(\) first"):
        rospy.spin()
    rospy.init_node("spinner", disable_signals=True)
    threading.Timer(0.2, rospy.signal_shutdown, args=("bye",)).start()
    rospy.spin()
    assert rospy.is_shutdown()


def test_timer_calls_back_periodically(rospy: ModuleType) -> None:
    rospy.init_node("timed", disable_signals=True)
    events: list[Any] = []
    timer = rospy.Timer(rospy.Duration(0, 20_000_000), events.append)
    wait_for(lambda: len(events) >= 3, what="three timer events")
    timer.shutdown()
    assert events[1].last_real is not None


def test_a_timer_ends_quietly_when_its_node_shuts_down(
    rospy: ModuleType, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Even when the client already names another node (a process that starts a second one,
    as each test here does): the timer's thread ends without an exception."""
    rospy.init_node("timed_then_gone", disable_signals=True)
    timer = rospy.Timer(rospy.Duration(5), lambda event: None)
    wait_for(timer.is_alive, what="the timer's thread")
    raised: list[BaseException | None] = []
    monkeypatch.setattr(threading, "excepthook", lambda args: raised.append(args.exc_value))
    first = state.CLIENT
    monkeypatch.setattr(state, "CLIENT", state.Client())
    first.signal_shutdown("over")
    timer.join(10)
    assert not timer.is_alive()
    assert raised == []


def _nodes(rospy: ModuleType) -> set[str]:
    code, _, state = rospy.get_master().getSystemState()  # the whole reply, as rospy's
    assert code == 1
    return {n for group in state for _, names in group for n in names}


def test_a_callback_may_shut_the_node_down(rospy: ModuleType) -> None:
    rospy.init_node("quitter", disable_signals=True)
    rospy.Subscriber("/quit", String, lambda msg: rospy.signal_shutdown(msg.data))
    pub = rospy.Publisher("/quit", String, queue_size=1)
    wait_for(lambda: pub.get_num_connections() == 1)
    pub.publish("enough")
    wait_for(rospy.is_shutdown, what="the shutdown")
    wait_for(lambda: "/quitter" not in _nodes(rospy), what="the node to unregister")
