"""In-process links between nodes of one process: no socket, no serialization, each subscriber
its own copy, latching and queues as over TCPROS, and other processes still see the topic."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.message import serialize_frame
from rosx.node import Node, RawMessage
from rosx.node import receiver as receiver_module
from rosx.node.local import LocalLink
from tests.support.cli import rosx_process
from tests.support.procs import wait_for

Twist = get_message_class("geometry_msgs/Twist")
Vector3 = get_message_class("geometry_msgs/Vector3")
PoseStamped = get_message_class("geometry_msgs/PoseStamped")
String = get_message_class("std_msgs/String")


def twist(x: float) -> Any:
    return Twist(linear=Vector3(x=x))


def linked(pub: Any, sub: Any) -> Callable[[], bool]:
    return lambda: pub.get_num_connections() > 0 and sub.get_num_connections() > 0


def test_nodes_of_one_process_link_without_a_socket(make_node: Callable[..., Node]) -> None:
    a, b = make_node("inproc_pub"), make_node("inproc_sub")
    got: list[Any] = []
    sub = b.subscribe("/direct", Twist, got.append)
    pub = a.advertise("/direct", Twist, queue_size=10)
    wait_for(linked(pub, sub))
    publication = pub.publication
    assert publication.links == ()  # no TCPROS subscriber: nothing was accepted on a socket
    (link,) = publication.local_links
    assert list(sub.subscription.streams.values()) == [link]
    assert isinstance(link, LocalLink)
    assert link.sock is None
    pub.publish(twist(1.5))
    wait_for(lambda: got)
    assert got[0].linear.x == 1.5
    assert got[0]._connection_header["callerid"] == "/inproc_pub"
    assert got[0]._connection_header["md5sum"] == Twist._md5sum
    assert publication.bytes_published == 0  # nothing serialized


def test_same_messages_in_the_same_order(make_node: Callable[..., Node]) -> None:
    a, b = make_node("order_pub"), make_node("order_sub")
    got: list[Any] = []
    sub = b.subscribe("/pose", PoseStamped, got.append)
    pub = a.advertise("/pose", PoseStamped, queue_size=None)
    wait_for(linked(pub, sub))
    for i in range(2000):
        msg = PoseStamped()
        msg.header.frame_id = f"f{i}"
        msg.pose.position.x = float(i)
        pub.publish(msg)
    wait_for(lambda: len(got) == 2000)
    assert [m.pose.position.x for m in got] == [float(i) for i in range(2000)]
    assert [m.header.frame_id for m in got] == [f"f{i}" for i in range(2000)]
    assert [m.header.seq for m in got] == list(range(1, 2001))


def test_a_node_that_counts_as_roscpp_numbers_its_headers_from_0(
    make_node: Callable[..., Node],
) -> None:
    """rospy's first ``header.seq`` is 1 (above); roscpp's is 0, and rosx's C++ programs
    (map_server's latched map, stageros's odometry) count as roscpp does."""
    a, b = make_node("cpp_pub", first_seq=0), make_node("cpp_sub")
    got: list[Any] = []
    sub = b.subscribe("/cpp_pose", PoseStamped, got.append)
    pub = a.advertise("/cpp_pose", PoseStamped, queue_size=None)
    wait_for(linked(pub, sub))
    for _ in range(3):
        pub.publish(PoseStamped())
    wait_for(lambda: len(got) == 3)
    assert [m.header.seq for m in got] == [0, 1, 2]


def test_the_local_thread_is_ready_when_the_link_connects(make_node: Callable[..., Node]) -> None:
    """Before the first message: a publisher may flood as soon as it sees the subscriber, and
    a thread still starting then would wait for the GIL while the queue overflows."""
    a, b = make_node("ready_pub"), make_node("ready_sub")
    sub = b.subscribe("/ready", Twist, lambda m: None)
    receiver = sub.subscription.receiver
    assert receiver._local is None  # nothing in this process publishes it yet
    pub = a.advertise("/ready", Twist, queue_size=100)
    wait_for(linked(pub, sub))
    thread = receiver._local
    assert thread is not None
    assert thread.is_alive()
    assert receiver._doorbell is not None


def test_an_asynchronous_flood_from_the_start_loses_nothing(
    make_node: Callable[..., Node],
) -> None:
    """A publisher with a queue floods from its first message on: the callbacks keep up (the
    queue drops only past `LOCAL_HIGH_WATER` waiting messages). On a machine so busy that the
    callbacks' thread is kept off the CPU that long, the oldest waiting go, as designed: every
    message is then handled or counted as dropped, in order, the newest handled."""
    a, b = make_node("flood_pub"), make_node("flood_sub")
    got: list[float] = []
    sub = b.subscribe("/flood", Twist, lambda m: got.append(m.linear.x))
    pub = a.advertise("/flood", Twist, queue_size=100)
    wait_for(linked(pub, sub))
    for i in range(30_000):
        pub.publish(twist(i))
    receiver = sub.subscription.receiver
    wait_for(lambda: len(got) + receiver.dropped == 30_000, timeout=60, what="30 000 messages")
    if receiver.dropped:
        assert got == sorted(set(got)) and got[-1] == 29_999.0
    else:
        assert got == [float(i) for i in range(30_000)]


def test_a_synchronous_publisher_loses_nothing_past_the_high_water(
    make_node: Callable[..., Node],
) -> None:
    a, b = make_node("sync_pub"), make_node("sync_sub")
    got: list[float] = []
    sub = b.subscribe("/many", Twist, lambda m: got.append(m.linear.x))
    pub = a.advertise("/many", Twist, queue_size=None)
    wait_for(linked(pub, sub))
    for i in range(30_000):
        pub.publish(twist(i))
    wait_for(lambda: len(got) == 30_000, timeout=60)
    assert got == [float(i) for i in range(30_000)]


def test_the_local_thread_wakes_for_a_flood_and_after_a_pause(
    make_node: Callable[..., Node],
) -> None:
    """The local thread waits for a flood's next message on a condition, and after a pause on
    a pipe: a message gets through either way, and the pipe goes with the subscriber."""
    a, b = make_node("wake_pub"), make_node("wake_sub")
    got: list[float] = []
    sub = b.subscribe("/wake", Twist, lambda m: got.append(m.linear.x))
    pub = a.advertise("/wake", Twist, queue_size=None)
    wait_for(linked(pub, sub))
    receiver = sub.subscription.receiver
    for i in range(5):
        pub.publish(twist(i))
        wait_for(lambda: len(got) == i + 1)  # noqa: B023 - awaited before `i` changes
        wait_for(lambda: receiver._sleeping == receiver_module._ON_PIPE)  # the pause
    for i in range(5, 3000):  # a flood: most wake-ups find the thread on the condition
        pub.publish(twist(i))
    wait_for(lambda: len(got) == 3000)
    assert got == [float(i) for i in range(3000)]
    assert receiver._doorbell is not None
    thread = receiver._local
    assert thread is not None
    sub.unregister()
    wait_for(lambda: not thread.is_alive())
    assert receiver._doorbell is None  # both ends closed


def test_each_subscriber_gets_a_copy_taken_at_publish(make_node: Callable[..., Node]) -> None:
    a, b, c = make_node("copy_pub"), make_node("copy_sub1"), make_node("copy_sub2")
    first: list[Any] = []
    second: list[Any] = []
    third: list[Any] = []
    gate = threading.Event()

    def mutate(msg: Any) -> None:
        gate.wait(10)
        first.append(msg.linear.x)
        msg.linear.x = -1.0  # a callback changing its message changes nobody else's

    sub1 = b.subscribe("/shared", Twist, mutate)
    b.subscribe("/shared", Twist, second.append)
    sub3 = c.subscribe("/shared", Twist, third.append)
    pub = a.advertise("/shared", Twist)
    wait_for(lambda: linked(pub, sub1)() and sub3.get_num_connections() > 0)
    msg = twist(1.0)
    pub.publish(msg)
    msg.linear.x = 2.0  # the publisher reuses its message, as rospy code often does
    pub.publish(msg)
    gate.set()
    wait_for(lambda: len(first) == 2 and len(second) == 2 and len(third) == 2)
    assert first == [1.0, 2.0]
    assert [m.linear.x for m in second] == [1.0, 2.0]
    assert [m.linear.x for m in third] == [1.0, 2.0]
    assert all(m is not msg for m in second + third)
    assert second[0] is not third[0]


def test_a_late_subscriber_gets_the_latched_message(make_node: Callable[..., Node]) -> None:
    a, b, c = make_node("latch_pub"), make_node("latch_sub1"), make_node("latch_sub2")
    pub = a.advertise("/map", String, latch=True)
    msg = String(data="first")
    pub.publish(msg)
    msg.data = "second"
    pub.publish(msg)
    msg.data = "changed after publishing"
    got: list[Any] = []

    def spoil(m: Any) -> None:
        got.append(m.data)
        m.data = "spoiled by a callback"

    b.subscribe("/map", String, spoil)
    wait_for(lambda: got)
    late: list[str] = []
    c.subscribe("/map", String, lambda m: late.append(m.data))
    wait_for(lambda: late)
    assert got == ["second"]
    assert late == ["second"]
    wait_for(lambda: len(pub.publication.local_links) == 2)
    assert pub.publication.links == ()


def test_a_raw_subscriber_gets_the_serialized_bytes(make_node: Callable[..., Node]) -> None:
    a, b = make_node("raw_pub"), make_node("raw_sub")
    got: list[Any] = []
    sub = b.subscribe("/raw", None, got.append)
    pub = a.advertise("/raw", Twist)
    wait_for(linked(pub, sub))
    pub.publish(twist(3.0))
    wait_for(lambda: got)
    assert isinstance(got[0], RawMessage)
    assert got[0]._buff == serialize_frame(twist(3.0))[4:]
    assert got[0].type == "geometry_msgs/Twist"


def test_other_processes_see_the_topic_and_the_link(
    make_node: Callable[..., Node], master: str
) -> None:
    a, b = make_node("talker_ip"), make_node("listener_ip")
    got: list[str] = []
    sub = b.subscribe("/chatter_ip", String, lambda m: got.append(m.data))
    pub = a.advertise("/chatter_ip", String, queue_size=10)
    wait_for(linked(pub, sub))
    stop = threading.Event()

    def talk() -> None:
        count = 0
        while not stop.wait(0.02):
            pub.publish(String(data=f"hello {count}"))
            count += 1

    talker = threading.Thread(target=talk, daemon=True)
    talker.start()
    try:
        info = rosx_process("rosnode", "info", "/talker_ip", ROS_MASTER_URI=master)
        echo = rosx_process("rostopic", "echo", "-n", "2", "/chatter_ip", ROS_MASTER_URI=master)
    finally:
        stop.set()
        talker.join()
    assert info.status == 0, info.err
    assert (
        " * topic: /chatter_ip\n"
        "    * to: /listener_ip\n"
        "    * direction: outbound\n"
        "    * transport: INTRAPROCESS\n"
    ) in info.out
    assert echo.status == 0, echo.err
    lines = echo.out.splitlines()
    assert lines[0].startswith('data: "hello ')
    assert lines[1:2] == ["---"]
    assert len(lines) == 4
    assert got  # the in-process subscriber kept receiving
    wait_for(lambda: len(pub.publication.links) == 0)  # echo's TCPROS link has gone
