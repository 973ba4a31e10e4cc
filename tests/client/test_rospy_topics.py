"""rospy's Publisher, Subscriber, wait_for_message and AnyMsg over rosx nodes."""

from __future__ import annotations

import warnings
from collections.abc import Callable
from types import ModuleType
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node
from tests.support.procs import wait_for

String = get_message_class("std_msgs/String")
Twist = get_message_class("geometry_msgs/Twist")
Vector3 = get_message_class("geometry_msgs/Vector3")


def test_messages_reach_callbacks_with_their_arguments(rospy: ModuleType) -> None:
    rospy.init_node("both", disable_signals=True)
    got: list[tuple[str, str]] = []
    sub = rospy.Subscriber("chatter", String, lambda m, extra: got.append((m.data, extra)), "x")
    pub = rospy.Publisher("chatter", String, queue_size=10)
    wait_for(lambda: pub.get_num_connections() == 1 and sub.get_num_connections() == 1)
    pub.publish(String(data="one"))
    pub.publish("two")
    pub.publish(data="three")
    wait_for(lambda: len(got) == 3, what="three messages")
    assert got == [("one", "x"), ("two", "x"), ("three", "x")]
    sub.unregister()
    sub.unregister()
    assert sub.get_num_connections() == 0


def test_topics_made_before_init_node_register_when_it_runs(
    rospy: ModuleType, make_node: Callable[[str], Node]
) -> None:
    got: list[Any] = []
    pub = rospy.Publisher("/cmd_vel", Twist, queue_size=10)
    rospy.Subscriber("/echo", String, got.append)
    assert pub.get_num_connections() == 0
    with pytest.raises(rospy.ROSException, match="has not been initialized yet"):
        pub.publish(Twist())
    with pytest.raises(ValueError, match="~name topics cannot be created before init_node"):
        rospy.Publisher("~private", Twist, queue_size=1)
    rospy.init_node("late", disable_signals=True)
    other = make_node("other")
    seen: list[Any] = []
    other.subscribe("/cmd_vel", Twist, seen.append)
    echo = other.advertise("/echo", String, queue_size=1)
    wait_for(lambda: pub.get_num_connections() == 1 and echo.get_num_connections() == 1)
    pub.publish(Twist(linear=Vector3(x=1.0)))
    echo.publish(String(data="back"))
    wait_for(lambda: bool(seen and got), what="both directions")
    assert seen[0].linear.x == 1.0 and got[0].data == "back"


def test_latched_messages_reach_late_subscribers(rospy: ModuleType) -> None:
    rospy.init_node("latcher", disable_signals=True)
    pub = rospy.Publisher("/latched", String, latch=True, queue_size=1)
    pub.publish(String(data="kept"))
    assert rospy.wait_for_message("/latched", String, timeout=5).data == "kept"


def test_wait_for_message_times_out_with_rospys_text(rospy: ModuleType) -> None:
    rospy.init_node("waiter", disable_signals=True)
    with pytest.raises(rospy.ROSException, match=r"^timeout exceeded while waiting for message"):
        rospy.wait_for_message("/silent", String, timeout=rospy.Duration(0, 100_000_000))


def test_publish_checks_what_it_is_given(rospy: ModuleType) -> None:
    rospy.init_node("checker", disable_signals=True)
    pub = rospy.Publisher("/typed", Twist, queue_size=1)
    with pytest.raises(TypeError, match=r"expected \[geometry_msgs/Vector3\] but got \[std_msgs"):
        pub.publish(String())
    with pytest.raises(rospy.ROSSerializationException):
        pub.publish(Twist(linear=Vector3(x="fast")))
    pub.unregister()
    with pytest.raises(rospy.ROSException, match=r"^publish\(\) to an unregistered\(\) handle$"):
        pub.publish(Twist())


def test_bad_arguments_are_refused_with_rospys_texts(rospy: ModuleType) -> None:
    with pytest.raises(ValueError, match=r"^topic name is not a non-empty string$"):
        rospy.Publisher("", String, queue_size=1)
    with pytest.raises(ValueError, match=r"^topic parameter 'data_class' is not initialized$"):
        rospy.Subscriber("/x", None)
    with pytest.raises(ValueError, match=r"^data_class \[type\] is not a message data class$"):
        rospy.Publisher("/x", int, queue_size=1)


def test_a_publisher_without_queue_size_warns_as_rospy(rospy: ModuleType) -> None:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        rospy.Publisher("/sync", String)
    assert caught[0].category is SyntaxWarning
    assert "explicit keyword argument 'queue_size'" in str(caught[0].message)


def test_a_failing_callback_is_logged_and_the_topic_goes_on(
    rospy: ModuleType, capsys: pytest.CaptureFixture[str]
) -> None:
    rospy.init_node("fragile", disable_signals=True)
    got: list[str] = []

    def callback(msg: Any) -> None:
        if msg.data == "bad":
            raise RuntimeError("broken callback")
        got.append(msg.data)

    rospy.Subscriber("/fragile", String, callback)
    pub = rospy.Publisher("/fragile", String, queue_size=10)
    wait_for(lambda: pub.get_num_connections() == 1)
    pub.publish("bad")
    pub.publish("good")
    wait_for(lambda: got == ["good"], what="the good message")
    err = capsys.readouterr().err
    assert "[ERROR]" in err and "bad callback: <function" in err
    assert "RuntimeError: broken callback" in err and "Traceback" in err


def test_anymsg_receives_any_type_as_bytes(rospy: ModuleType) -> None:
    rospy.init_node("relay", disable_signals=True)
    got: list[Any] = []
    rospy.Subscriber("/raw", rospy.AnyMsg, got.append)
    pub = rospy.Publisher("/raw", String, queue_size=1)
    wait_for(lambda: pub.get_num_connections() == 1)
    pub.publish("hi")
    wait_for(lambda: bool(got), what="a raw message")
    assert got[0]._buff == b"\x02\x00\x00\x00hi"
    assert got[0]._connection_header["type"] == "std_msgs/String"
    relay = rospy.Publisher("/relayed", String, queue_size=1)
    relay.publish(got[0])  # sent as the bytes it holds
    with pytest.raises(rospy.ROSException, match="AnyMsg does not accept arguments"):
        rospy.AnyMsg(1)
