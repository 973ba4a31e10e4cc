"""Topics between rosx nodes in one process: delivery, latching, queues, raw subscriptions,
publisher updates, unregistration and the Slave API's view of the connections.

Every test runs three times: over the in-process links nodes of one process use by default, over
the Unix sockets rosx nodes of one machine use (``rosx.node.local.ENABLED`` off), and over TCPROS
(``rosx.node.unixros.ENABLED`` off too), the path to ROS 1 nodes and other machines."""

from __future__ import annotations

import ast
import contextlib
import os
import re
import threading
from collections.abc import Callable, Iterator
from typing import Any
from xmlrpc.server import SimpleXMLRPCServer

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node, RawMessage, local, unixros
from rosx.node.node import WORKERS
from rosx.transport.client import call
from tests.support.procs import wait_for

Twist = get_message_class("geometry_msgs/Twist")
Vector3 = get_message_class("geometry_msgs/Vector3")
String = get_message_class("std_msgs/String")
Image = get_message_class("sensor_msgs/Image")
PointCloud2 = get_message_class("sensor_msgs/PointCloud2")
PointField = get_message_class("sensor_msgs/PointField")

# rosnode's pattern for the connection text of getBusInfo (tools/rosnode).
CONNECTION_PATTERN = re.compile(r"\w+ connection on port (\d+) to \[(.*) on socket (\d+)\]")


@pytest.fixture(autouse=True, params=["INTRAPROCESS", "UNIXROS", "TCPROS"])
def transport(request: pytest.FixtureRequest, monkeypatch: pytest.MonkeyPatch) -> str:
    """The transport nodes of this process use among themselves in the test."""
    monkeypatch.setattr(local, "ENABLED", request.param == "INTRAPROCESS")
    monkeypatch.setattr(unixros, "ENABLED", request.param != "TCPROS")
    return str(request.param)


def twist(x: float) -> Any:
    return Twist(linear=Vector3(x=x))


def connected(pub: Any, sub: Any) -> Callable[[], bool]:
    return lambda: pub.get_num_connections() > 0 and sub.get_num_connections() > 0


def test_twist_flows_between_two_nodes(make_node: Callable[..., Node]) -> None:
    talker, listener = make_node("talker"), make_node("listener")
    got: list[Any] = []
    sub = listener.subscribe("/cmd_vel", Twist, got.append)
    pub = talker.advertise("/cmd_vel", Twist, queue_size=10)
    wait_for(connected(pub, sub))
    for i in range(100):
        pub.publish(twist(i))
    wait_for(lambda: len(got) == 100)
    assert [m.linear.x for m in got] == [float(i) for i in range(100)]
    assert got[0]._connection_header["callerid"] == "/talker"
    assert got[0]._connection_header["type"] == "geometry_msgs/Twist"


def test_a_flood_arrives_whole_and_in_order_and_its_last_message_is_the_latch(
    make_node: Callable[..., Node],
) -> None:
    """A publisher writes a flood's frames together while its subscriber is behind
    (`rosx.node.outgoing`): every message arrives, in order, as published, with a bounded
    queue too, and the latch a late subscriber gets is the last one."""
    talker, listener, late_node = make_node("talker"), make_node("listener"), make_node("late")
    got: list[Any] = []
    bounded: list[float] = []
    sub = listener.subscribe("/flood", Twist, got.append, queue_size=None)
    sub_bounded = late_node.subscribe("/flood", Twist, lambda m: bounded.append(m.linear.x))
    pub = talker.advertise("/flood", Twist, queue_size=5000, latch=True)
    wait_for(lambda: pub.get_num_connections() == 2 and sub.get_num_connections() == 1)
    wait_for(lambda: sub_bounded.get_num_connections() == 1)
    msg = Twist()
    for i in range(3000):
        msg.linear.x = float(i)
        msg.angular.z = -float(i)
        pub.publish(msg)
    wait_for(lambda: len(got) == 3000 and len(bounded) == 3000, what="the flood")
    assert [(m.linear.x, m.angular.z) for m in got] == [(float(i), -float(i)) for i in range(3000)]
    assert bounded == [float(i) for i in range(3000)]
    latched: list[float] = []
    make_node("later").subscribe("/flood", Twist, lambda m: latched.append(m.linear.x))
    wait_for(lambda: latched, what="the latch")
    assert latched == [2999.0]


def test_callbacks_run_on_a_thread_of_their_own(make_node: Callable[..., Node]) -> None:
    a, b = make_node("a"), make_node("b")
    threads: list[str] = []
    sub = b.subscribe("/t", Twist, lambda m: threads.append(threading.current_thread().name))
    pub = a.advertise("/t", Twist)
    wait_for(connected(pub, sub))
    pub.publish(twist(1))
    wait_for(lambda: threads)
    assert threads[0].startswith("rosx-sub/t")
    assert threads[0] != threading.current_thread().name


def test_latched_message_reaches_late_subscribers(make_node: Callable[..., Node]) -> None:
    a, b = make_node("latcher"), make_node("late")
    pub = a.advertise("/latched", String, latch=True)
    pub.publish(String(data="first"))
    pub.publish(String(data="last"))
    got: list[str] = []
    b.subscribe("/latched", String, lambda m: got.append(m.data))
    wait_for(lambda: got)
    assert got == ["last"]
    # A second subscriber of the same topic in the same node gets the latch too.
    again: list[str] = []
    b.subscribe("/latched", String, lambda m: again.append(m.data))
    wait_for(lambda: again)
    assert again == ["last"]
    assert got == ["last"]


def test_a_topic_that_starts_latching_keeps_what_it_publishes_next(
    make_node: Callable[..., Node], transport: str
) -> None:
    """A second publisher handle asking for a latch turns it on for the topic (as in rospy),
    though one subscriber was already served without one."""
    a, b, c = make_node("talker"), make_node("listener"), make_node("late")
    got: list[str] = []
    sub = b.subscribe("/news", String, lambda m: got.append(m.data))
    pub = a.advertise("/news", String, queue_size=10)
    wait_for(connected(pub, sub))
    pub.publish(String(data="before"))
    wait_for(lambda: got == ["before"])
    a.advertise("/news", String, queue_size=10, latch=True)
    pub.publish(String(data="after"))
    wait_for(lambda: got == ["before", "after"])
    late: list[str] = []
    c.subscribe("/news", String, lambda m: late.append(m.data))
    wait_for(lambda: late)
    assert late == ["after"]
    if transport != "INTRAPROCESS":  # what went out serialized: two frames of 4 + 4 + 6 and 5
        _, _, (publications, _, _) = call(a.uri, "getBusStats", "/test")
        assert [p[:2] for p in publications if p[0] == "/news"] == [["/news", 14 + 13]]


def test_late_subscribers_get_the_latch_on_the_nodes_workers(
    make_node: Callable[..., Node],
) -> None:
    """Many callbacks added late each get the latched message once, run by the node's bounded
    pool of workers rather than by a new thread each."""
    a, b = make_node("latcher2"), make_node("late2")
    pub = a.advertise("/latched2", String, latch=True)
    pub.publish(String(data="kept"))
    first: list[str] = []
    b.subscribe("/latched2", String, lambda m: first.append(m.data))
    wait_for(lambda: first)
    runs: list[tuple[int, str, str]] = []

    def late(index: int) -> Callable[[Any], None]:
        return lambda m: runs.append((index, m.data, threading.current_thread().name))

    for index in range(3 * WORKERS):
        b.subscribe("/latched2", String, late(index))
    wait_for(lambda: len(runs) == 3 * WORKERS)
    assert sorted(index for index, _, _ in runs) == list(range(3 * WORKERS))
    assert {data for _, data, _ in runs} == {"kept"}
    names = {name for _, _, name in runs}
    assert all(name.startswith("rosx-worker/late2") for name in names)
    assert len(names) <= WORKERS
    assert first == ["kept"]


def test_subscriber_queue_drops_the_oldest(make_node: Callable[..., Node]) -> None:
    a, b = make_node("fast"), make_node("slow")
    release = threading.Event()
    got: list[float] = []

    def slow(msg: Any) -> None:
        got.append(msg.linear.x)
        release.wait(10)

    sub = b.subscribe("/flood", Twist, slow, queue_size=2)
    pub = a.advertise("/flood", Twist, queue_size=100)
    wait_for(connected(pub, sub))
    pub.publish(twist(0))
    wait_for(lambda: got)
    for i in range(1, 10):
        pub.publish(twist(i))
    wait_for(lambda: sub.subscription.connection_count() == 1)
    release.set()
    wait_for(lambda: len(got) == 3)
    assert got == [0.0, 8.0, 9.0]


def test_a_subscriber_whose_queue_dropped_messages_still_catches_up(
    make_node: Callable[..., Node],
) -> None:
    """Messages a bounded subscriber queue dropped are never handled: once the callbacks have
    run for the rest, the subscriber has caught up and a drain of it is done (what ``rosbag
    record`` waits for when it stops, and actionlib's client before each result)."""
    a, b = make_node("fast"), make_node("slow")
    release = threading.Event()
    got: list[float] = []

    def slow(msg: Any) -> None:
        got.append(msg.linear.x)
        release.wait(10)

    sub = b.subscribe("/flood", Twist, slow, queue_size=2)
    pub = a.advertise("/flood", Twist, queue_size=None)
    wait_for(connected(pub, sub))
    pub.publish(twist(0))
    wait_for(lambda: got)
    for i in range(1, 10):
        pub.publish(twist(i))
    wait_for(lambda: pub.delivered_to() == {"/slow"}, what="the messages sent")
    drain = sub.drain()  # everything is with this host: read, or in the socket's buffer
    assert not sub.caught_up()  # the first callback is held
    release.set()
    wait_for(drain.done, what="the drain")
    assert sub.caught_up()
    assert got == [0.0, 8.0, 9.0]
    pub.publish(twist(10))  # and it goes on: the next message is handled, then caught up
    wait_for(lambda: got[-1:] == [10.0])
    wait_for(sub.caught_up, what="the callbacks")


def test_a_stalled_subscriber_holds_up_nobody(make_node: Callable[..., Node]) -> None:
    # ROS 1's semantics: each subscriber has its own queue at the publisher (queue_size,
    # drop-oldest), so one whose callback never returns loses messages; nobody else does.
    source, good_node, stuck_node = (
        make_node("fan_pub"),
        make_node("fan_good"),
        make_node("fan_stuck"),
    )
    release = threading.Event()
    stuck: list[int] = []
    good: list[int] = []

    def never_returns(msg: Any) -> None:
        stuck.append(msg.header.seq)
        release.wait(30)

    s1 = stuck_node.subscribe("/fan", Image, never_returns, queue_size=1)
    s2 = good_node.subscribe("/fan", Image, lambda m: good.append(m.header.seq), queue_size=1)
    pub = source.advertise("/fan", Image, queue_size=2)
    wait_for(
        lambda: (
            pub.get_num_connections() == 2
            and s1.get_num_connections() == 1
            and s2.get_num_connections() == 1
        )
    )
    image = Image(height=512, width=512, encoding="rgba8", step=2048, data=bytes(1 << 20))
    try:
        # 24 MiB: far more than the stalled subscriber's socket (or queue) holds.
        for i in range(1, 25):
            pub.publish(image)
            wait_for(lambda: len(good) == i)  # noqa: B023 - called before i changes
            if i == 1:
                # The stalled callback holds the first message before the next is published:
                # with queue_size=1 a second one queued first would replace it (as in ROS 1).
                wait_for(lambda: stuck == [1])
        assert good == list(range(1, 25))
        assert stuck == [1]
    finally:
        release.set()


def test_raw_subscription_learns_the_type(make_node: Callable[..., Node]) -> None:
    a, b = make_node("typed"), make_node("any")
    got: list[RawMessage] = []
    sub = b.subscribe("/raw", None, got.append)
    assert sub.type == "*"
    pub = a.advertise("/raw", Twist)
    wait_for(connected(pub, sub))
    pub.publish(twist(2.5))
    wait_for(lambda: got)
    raw = got[0]
    assert isinstance(raw, RawMessage)
    assert raw.type == "geometry_msgs/Twist"
    assert raw.md5sum == Twist._md5sum
    assert "MSG: geometry_msgs/Vector3" in raw.message_definition
    assert Twist().deserialize(raw._buff).linear.x == 2.5
    assert b.subscriptions["/raw"].type == "*"


def test_a_raw_subscriber_takes_a_flood_in_order_each_message_its_own(
    make_node: Callable[..., Node],
) -> None:
    """A raw subscriber reads a flood on the reader's quick paths as a typed one does: every
    message in order, each a `RawMessage` of its own with its bytes and the publisher's type."""
    a, b = make_node("flooder"), make_node("raw_taker")
    got: list[RawMessage] = []
    sub = b.subscribe("/raw_flood", None, got.append)
    pub = a.advertise("/raw_flood", Twist, queue_size=None)
    wait_for(connected(pub, sub))
    for i in range(3000):
        pub.publish(twist(float(i)))
    wait_for(lambda: len(got) == 3000, what="the flood")
    assert [Twist().deserialize(raw._buff).linear.x for raw in got] == [
        float(i) for i in range(3000)
    ]
    assert {raw.type for raw in got} == {"geometry_msgs/Twist"}
    assert {type(raw._buff) for raw in got} == {bytes}
    assert len({id(raw) for raw in got}) == 3000


def test_publisher_update_connects_a_new_publisher(make_node: Callable[..., Node]) -> None:
    listener = make_node("waiting")
    got: list[str] = []
    sub = listener.subscribe("/news", String, lambda m: got.append(m.data))
    first = make_node("first").advertise("/news", String)
    wait_for(lambda: first.get_num_connections() == 1)
    second_node = make_node("second")
    second = second_node.advertise("/news", String)
    wait_for(lambda: second.get_num_connections() == 1 and sub.get_num_connections() == 2)
    first.publish(String(data="one"))
    second.publish(String(data="two"))
    wait_for(lambda: len(got) == 2)
    assert sorted(got) == ["one", "two"]
    # A publisher that goes away is dropped when the master says so.
    second_node.shutdown("gone")
    wait_for(lambda: sub.get_num_connections() == 1)


@contextlib.contextmanager
def fake_publisher(answer: list[Any]) -> Iterator[str]:
    """A Slave API answering every ``requestTopic`` with ``answer``; yields its URI."""
    server = SimpleXMLRPCServer(("127.0.0.1", 0), logRequests=False)
    server.register_function(lambda *_: answer, "requestTopic")
    server.register_function(lambda *_: [1, "", [["/odd", "std_msgs/String"]]], "getPublications")
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()
        thread.join()


@pytest.mark.parametrize(
    ("uri", "answer", "error"),
    [
        ("http://127.0.0.1:1²/", None, "invalid host or port in URI 'http://127.0.0.1:1²/'"),
        (None, [1, "", ["TCPROS", "127.0.0.1", "1²"]], "invalid protocol choice"),
        (None, [1, "", ["TCPROS", "127.0.0.1", 70000]], "invalid protocol choice"),
    ],
    ids=["uri", "port-text", "port-range"],
)
def test_a_publisher_that_cannot_be_called_is_one_logged_line(
    make_node: Callable[..., Node], master: str, uri: str | None, answer: Any, error: str
) -> None:
    lines: list[str] = []
    listener = make_node("odd_listener", console=lambda level, line: lines.append(line))
    with contextlib.ExitStack() as stack:
        uri = uri or stack.enter_context(fake_publisher(answer))
        call(master, "registerPublisher", "/odd_pub", "/odd", "std_msgs/String", uri)
        try:
            listener.subscribe("/odd", String, lambda m: None)
            wait_for(lambda: any(error in line for line in lines), what="the error")
        finally:
            call(master, "unregisterPublisher", "/odd_pub", "/odd", uri)
    (line,) = [line for line in lines if error in line]
    assert line.startswith("[ERROR] [") and "[/odd]" in line and "\n" not in line


def test_several_subscribers_share_a_topic(make_node: Callable[..., Node]) -> None:
    a, b = make_node("one_pub"), make_node("two_subs")
    first: list[float] = []
    second: list[float] = []
    b.subscribe("/shared", Twist, lambda m: first.append(m.linear.x))
    sub = b.subscribe("/shared", Twist, lambda m: second.append(m.linear.x))
    pub = a.advertise("/shared", Twist)
    wait_for(connected(pub, sub))
    pub.publish(twist(7))
    wait_for(lambda: first and second)
    assert first == second == [7.0]
    assert pub.get_num_connections() == 1


def test_unregister_and_shutdown_leave_the_master(
    make_node: Callable[..., Node], master: str
) -> None:
    node = make_node("leaver")
    pub = node.advertise("/gone_pub", Twist)
    sub = node.subscribe("/gone_sub", Twist, lambda m: None)
    node.advertise_service(
        "/gone_srv", _srv("std_srvs/Empty"), lambda req: _srv("std_srvs/Empty")._response_class()
    )

    def state() -> list[Any]:
        return call(master, "getSystemState", "/test")[2]  # type: ignore[no-any-return]

    pubs, subs, srvs = state()
    assert ["/gone_pub", ["/leaver"]] in pubs
    assert ["/gone_sub", ["/leaver"]] in subs
    assert ["/gone_srv", ["/leaver"]] in srvs
    pub.unregister()
    sub.unregister()
    pubs, subs, _ = state()
    assert not any(name == "/gone_pub" for name, _ in pubs)
    assert not any(name == "/gone_sub" for name, _ in subs)
    node.shutdown("done")
    pubs, subs, srvs = state()
    assert not any("/leaver" in nodes for _, nodes in pubs + subs + srvs)
    assert node.is_shutdown()


def test_bus_info_describes_connections(make_node: Callable[..., Node], transport: str) -> None:
    a, b = make_node("info_pub"), make_node("info_sub")
    sub = b.subscribe("/info", Twist, lambda m: None)
    pub = a.advertise("/info", Twist)
    wait_for(connected(pub, sub))
    code, status, rows = call(a.uri, "getBusInfo", "/test")
    assert (code, status) == (1, "bus info")
    (row,) = [r for r in rows if r[4] == "/info"]
    assert row[1:6] == ["/info_sub", "o", transport, "/info", True]
    if transport == "INTRAPROCESS":  # as roscpp reports its intra-process links
        assert row[6] == "INTRAPROCESS"
    else:
        assert CONNECTION_PATTERN.match(row[6])
    code, _, rows = call(b.uri, "getBusInfo", "/test")
    (row,) = [r for r in rows if r[4] == "/info"]
    assert row[1:6] == [a.uri, "i", transport, "/info", True]
    if transport == "INTRAPROCESS":
        assert row[6] == "INTRAPROCESS"
    else:
        match = CONNECTION_PATTERN.match(row[6])
        assert match is not None
        if transport == "UNIXROS":  # the publisher's socket, and this process at the other end
            assert match.group(2) == f"{a.unixros_address()} (pid {os.getpid()})"
        else:
            assert match.group(2).endswith(f":{a.tcpros_address()[1]}")
    code, _, stats = call(a.uri, "getBusStats", "/test")
    assert code == 1
    assert any(entry[0] == "/info" for entry in stats[0])


def test_slave_api_answers_as_rospy(make_node: Callable[..., Node]) -> None:
    node = make_node("slave")
    node.advertise("/pubd", Twist)
    node.subscribe("/subd", String, lambda m: None)
    uri = node.uri
    assert call(uri, "getPid", "/x")[0] == 1
    assert call(uri, "getName", "/x") == [1, "", "/slave"]
    assert call(uri, "getUri", "/x") == [1, "", uri]
    assert call(uri, "getMasterUri", "/x")[2] == node.master_uri
    assert ["/pubd", "geometry_msgs/Twist"] in call(uri, "getPublications", "/x")[2]
    assert call(uri, "getSubscriptions", "/x")[2] == [["/subd", "std_msgs/String"]]
    assert call(uri, "requestTopic", "/x", "/nope", [["TCPROS"]]) == [
        -1,
        "Not a publisher of [/nope]",
        [],
    ]
    code, _, params = call(uri, "requestTopic", "/x", "/pubd", [["TCPROS"]])
    assert code == 1
    assert params == ["TCPROS", node.host, node.tcpros_address()[1]]
    assert call(uri, "requestTopic", "/x", "/pubd", [["UDPROS"]])[0] == 0
    assert call(uri, "getPid") == [-1, "missing required caller_id parameter", -1]
    assert call(uri, "getPid", "/x", 1) == [-1, "Error: bad call arity", -1]
    assert call(uri, "getPid", 5)[1] == "caller_id must be a string"
    assert call(uri, "publisherUpdate", "/x", "", [])[1] == (
        "ERROR: parameter [topic] must be a non-empty string"
    )
    assert call(uri, "paramUpdate", "/x", "/not/subscribed", 1) == [-1, "not subscribed", 0]


#: requestTopic's answers for protocols a publisher cannot serve, as a rospy publisher gives them
#: (Debian's rospy, asked the same).
NO_PROTOCOL = [0, "no supported protocol implementations", []]


@pytest.mark.parametrize(
    ("protocols", "answer"),
    [
        ([["UDPROS"]], NO_PROTOCOL),
        ([["tcpros"]], NO_PROTOCOL),
        ([[1]], NO_PROTOCOL),
        ([[True]], NO_PROTOCOL),
        (["TCPROS"], NO_PROTOCOL),
        ("TCPROS", NO_PROTOCOL),
        ({"a": 1}, NO_PROTOCOL),
        ([[]], [0, "Internal failure: list index out of range", []]),
        (5, [-1, "Error: invalid arguments: 'int' object is not iterable", []]),
        ([], [-1, "ERROR: parameter [protocols] must be specified and non-empty", []]),
    ],
)
def test_request_topic_without_a_usable_protocol_answers_as_rospy(
    make_node: Callable[..., Node], protocols: object, answer: list[Any]
) -> None:
    node = make_node("chooser")
    node.advertise("/offered", String)
    assert call(node.uri, "requestTopic", "/x", "/offered", protocols) == answer
    code, _, params = call(node.uri, "requestTopic", "/x", "/offered", [["UDPROS"], ["TCPROS"]])
    assert (code, params[0]) == (1, "TCPROS")


def test_slave_shutdown_stops_the_node(make_node: Callable[..., Node]) -> None:
    node = make_node("victim")
    reasons: list[str] = []
    node.on_shutdown(reasons.append)
    assert call(node.uri, "shutdown", "/master", "bye") == [1, "shutdown", 0]
    assert node.wait_for_shutdown(10)
    wait_for(lambda: reasons)
    assert reasons == ["external shutdown request from [/master]: [bye]"]


def _srv(name: str) -> Any:
    from rosx.msg.codec.classes import get_service_class

    return get_service_class(name)


def test_large_and_small_messages_arrive_whole_and_in_order(
    make_node: Callable[..., Node],
) -> None:
    a, b = make_node("big_pub"), make_node("big_sub")
    got: list[Any] = []
    sub = b.subscribe("/big", String, got.append)
    pub = a.advertise("/big", String, queue_size=None)
    wait_for(connected(pub, sub))
    sizes = [10, 3 << 20, 70_000, 5, 1 << 20, 64 * 1024, 64 * 1024 - 5, 200]
    texts = [chr(ord("a") + i) * size for i, size in enumerate(sizes)]
    for text in texts:
        pub.publish(String(data=text))
    wait_for(lambda: len(got) == len(texts))
    assert [m.data for m in got] == texts
    assert all(type(m.data) is str for m in got)


def test_images_arrive_as_published_though_the_message_changes_after(
    make_node: Callable[..., Node], transport: str
) -> None:
    """Large byte arrays are sent from the message itself (`rosx.msg.codec.parts`): what each
    subscriber gets is the message as it was at ``publish``, whatever the publisher does to
    the message next, in order; a raw subscriber gets the same bytes a whole frame holds."""
    a, b = make_node("camera"), make_node("viewer")
    got: list[Any] = []
    raw: list[RawMessage] = []
    sub = b.subscribe("/camera", Image, got.append)
    raw_sub = b.subscribe("/camera", None, raw.append)
    pub = a.advertise("/camera", Image, queue_size=None)
    wait_for(lambda: pub.get_num_connections() > 0 and sub.get_num_connections() > 0)
    wait_for(lambda: raw_sub.get_num_connections() > 0)
    msg = Image(height=1, encoding="mono8")
    published = []
    for i, size in enumerate([1 << 20, 100, 40_000, 3 << 20, 0, 32 * 1024]):
        msg.header.frame_id = f"frame {i}"
        msg.width = msg.step = size
        msg.data = bytes([i + 1]) * size if i != 2 else bytearray([i + 1]) * size
        pub.publish(msg)
        published.append(msg._frame())  # with the header's seq that publish gave it
    msg.data = b"changed after the last publish"
    wait_for(lambda: len(got) == len(published) and len(raw) == len(published))
    assert [m.header.frame_id for m in got] == [f"frame {i}" for i in range(len(published))]
    for message, frame in zip(got, published, strict=True):
        assert message._frame() == frame
    assert [bytes(r._buff) for r in raw] == [frame[4:] for frame in published]
    if transport != "INTRAPROCESS":  # every frame counted whole, once (one connection)
        _, _, (publications, _, _) = call(a.uri, "getBusStats", "/test")
        sent = sum(len(frame) for frame in published)
        assert [p[:2] for p in publications if p[0] == "/camera"] == [["/camera", sent]]


def test_clouds_read_in_parts_are_the_clouds_published(
    make_node: Callable[..., Node], transport: str
) -> None:
    """A subscriber whose callbacks all take point clouds reads a large one in parts, its data
    straight into the message's ``bytes`` (`rosx.node.incoming`): every cloud arrives as it was
    published, in order, whatever its size or the size of what precedes its data; a late
    callback and a late raw subscriber get the latched one whole."""
    a, b = make_node("lidar"), make_node("mapper")
    got: list[Any] = []
    sub = b.subscribe("/points", PointCloud2, got.append, queue_size=None)
    pub = a.advertise("/points", PointCloud2, queue_size=None, latch=True)
    wait_for(connected(pub, sub))
    fields = [PointField(name=n, offset=4 * i, datatype=7, count=1) for i, n in enumerate("xyz")]
    published = []
    # Large, small, large; one whose fields before the data outgrow what a reader looks at
    # first (read whole), then large ones again, the last with data under 64 KiB.
    for n, (size, frame_id) in enumerate(
        [
            (1 << 20, "a"),
            (10, "b"),
            (2 << 20, "c"),
            (300_000, "d" * 5000),
            (3 << 20, "e"),
            (70_000, "f"),
        ]
    ):
        cloud = PointCloud2(
            height=1, width=size // 12, fields=fields, point_step=12, is_dense=n % 2 == 0
        )
        cloud.header.frame_id = frame_id
        cloud.data = bytes([n + 1]) * size
        pub.publish(cloud)
        published.append(cloud._frame())
    wait_for(lambda: len(got) == len(published), what="every cloud")
    assert [m._frame() for m in got] == published
    assert all(type(m.data) is bytes for m in got)
    if transport != "INTRAPROCESS":
        _, _, (_, subscriptions, _) = call(b.uri, "getBusStats", "/test")
        stats = next(row for row in subscriptions if row[0] == "/points")[1]
        assert [row[1:3] for row in stats] == [[sum(len(f) for f in published), len(published)]]
    late: list[Any] = []
    b.subscribe("/points", PointCloud2, late.append)
    wait_for(lambda: late, what="the latch")
    assert late[0]._frame() == published[-1]
    raw: list[RawMessage] = []
    b.subscribe("/points", None, raw.append)
    wait_for(lambda: raw, what="the raw latch")
    assert bytes(raw[0]._buff) == published[-1][4:]


def test_large_frames_waiting_for_a_busy_callback_stay_whole(
    make_node: Callable[..., Node],
) -> None:
    """Large frames are read into a buffer that the next one may reuse once nothing views it
    (`rosx.node.incoming`): frames queued behind a busy callback (read from a second
    publisher while the first one's message is being handled), and the latch a late callback
    gets, keep what they held."""
    first, second, viewer = make_node("cam_one"), make_node("cam_two"), make_node("viewer")
    release = threading.Event()
    got: list[bytes] = []

    def busy(msg: Any) -> None:
        if not got:
            release.wait(10)
        got.append(msg.data)

    sub = viewer.subscribe("/burst", Image, busy, queue_size=None)
    pub_one = first.advertise("/burst", Image, queue_size=None)
    pub_two = second.advertise("/burst", Image, queue_size=None, latch=True)
    wait_for(lambda: sub.get_num_connections() == 2 and pub_two.get_num_connections() == 1)
    wait_for(lambda: pub_one.get_num_connections() == 1)
    pub_one.publish(Image(encoding="mono8", data=b"first"))
    wait_for(lambda: sub.subscription.receiver.received == 1)
    images = [bytes([n]) * (300_000 - n) for n in range(6)]  # each fits the last one's buffer
    for data in images:
        pub_two.publish(Image(encoding="mono8", data=data))
    wait_for(lambda: sub.subscription.receiver.received == 1 + len(images))
    release.set()
    wait_for(lambda: len(got) == 1 + len(images))
    assert got == [b"first", *images]
    late: list[bytes] = []
    viewer.subscribe("/burst", Image, lambda m: late.append(m.data))
    wait_for(lambda: late)
    assert late == images[-1:]


def test_a_latched_image_reaches_a_late_subscriber_whole(make_node: Callable[..., Node]) -> None:
    a, b = make_node("still"), make_node("late_viewer")
    pub = a.advertise("/still", Image, latch=True)
    first = Image(encoding="mono8", data=bytes(range(256)) * 8192)
    pub.publish(first)
    last = Image(encoding="mono8", data=bytes(reversed(range(256))) * 8192)
    pub.publish(last)
    last.data = b"changed after publishing"
    got: list[Any] = []
    b.subscribe("/still", Image, got.append)
    wait_for(lambda: got)
    assert got[0].data == bytes(reversed(range(256))) * 8192
    raw: list[RawMessage] = []
    b.subscribe("/still", None, raw.append)
    wait_for(lambda: raw)
    assert bytes(raw[0]._buff) == got[0]._frame()[4:]


class Greeter:
    """A publication's watcher: greets each new subscriber alone, notes who leaves."""

    def __init__(self) -> None:
        self.events: list[str] = []

    def subscribed(self, publish_one: Callable[[Any], None]) -> None:
        self.events.append("came")
        publish_one(String(data=f"welcome, number {self.events.count('came')}"))

    def unsubscribed(self, remaining: int) -> None:
        self.events.append(f"left, {remaining} remain")


def test_a_watcher_hears_of_subscribers_and_publishes_to_one_alone(
    make_node: Callable[..., Node],
) -> None:
    talker = make_node("talker")
    pub = talker.advertise("/greet", String, queue_size=10)
    greeter = Greeter()
    pub.publication.add_watcher(greeter)
    first: list[str] = []
    second: list[str] = []
    make_node("first").subscribe("/greet", String, lambda m: first.append(m.data))
    wait_for(lambda: first == ["welcome, number 1"], what="the first greeting")
    later = make_node("second").subscribe("/greet", String, lambda m: second.append(m.data))
    wait_for(lambda: second == ["welcome, number 2"], what="the second greeting")
    pub.publish(String(data="to all"))
    wait_for(lambda: first[-1:] == second[-1:] == ["to all"], what="the message to all")
    assert first == ["welcome, number 1", "to all"]
    later.unregister()
    wait_for(lambda: greeter.events[-1:] == ["left, 1 remain"], what="the second to leave")
    assert greeter.events == ["came", "came", "left, 1 remain"]


def test_delivered_to_names_the_subscribers_that_have_every_message(
    make_node: Callable[..., Node],
) -> None:
    a, b = make_node("deliver_pub"), make_node("deliver_sub")
    got: list[float] = []
    sub = b.subscribe("/delivered", Twist, lambda m: got.append(m.linear.x))
    pub = a.advertise("/delivered", Twist, queue_size=10)
    wait_for(connected(pub, sub))
    assert pub.delivered_to() == set()  # connected, sent nothing yet
    pub.publish(twist(1))
    wait_for(lambda: pub.delivered_to() == {"/deliver_sub"}, what="the delivery")
    wait_for(lambda: got == [1.0])


def test_drain_then_detach_hands_over_all_that_arrived(make_node: Callable[..., Node]) -> None:
    a, b = make_node("drain_pub"), make_node("drain_sub")
    gate = threading.Event()
    got: list[float] = []

    def held(msg: Any) -> None:
        gate.wait(10)
        got.append(msg.linear.x)

    sub = b.subscribe("/drained", Twist, held, queue_size=None)
    pub = a.advertise("/drained", Twist, queue_size=None)
    wait_for(connected(pub, sub))
    for i in range(50):
        pub.publish(twist(i))
    wait_for(lambda: pub.delivered_to() == {"/drain_sub"}, what="the messages sent")
    drain = sub.drain()  # everything is with this host: read, or in the socket's buffer
    assert not drain.done()  # the first callback is held
    gate.set()
    wait_for(drain.done, what="the drain")
    sub.detach()
    wait_for(sub.caught_up, what="the callbacks")
    assert got == [float(i) for i in range(50)]
    wait_for(lambda: sub.get_num_connections() == 0, what="the connection to end")


def test_a_node_asked_to_warns_as_rospy_when_it_refuses_a_subscriber_of_another_type(
    make_node: Callable[..., Node],
) -> None:
    """rospy's publishers warn of a subscriber refused, with its header (`rosx.client`'s and
    `rostopic`'s nodes ask for it); roscpp's, and rosx's other nodes, say nothing."""
    lines: list[tuple[int, str]] = []
    publisher = make_node(
        "/pose_talker", console=lambda level, line: lines.append((level, line)), warn_refusals=True
    )
    publisher.advertise("/mismatch", Vector3, queue_size=1)
    make_node("/twist_listener").subscribe("/mismatch", Twist, lambda _msg: None)
    wait_for(lambda: lines, what="the publisher's warning")
    [(level, line)] = lines
    assert level == 4  # WARN
    match = re.fullmatch(
        r"\[WARN\] \[\d+\.\d+\]: Could not process inbound connection: topic types do not "
        r"match: \[geometry_msgs/Twist\] vs\. \[geometry_msgs/Vector3\](\{.*\})",
        line,
        flags=re.DOTALL,
    )
    assert match is not None, line
    header = ast.literal_eval(match[1])
    assert (header["callerid"], header["topic"], header["type"]) == (
        "/twist_listener",
        "/mismatch",
        "geometry_msgs/Twist",
    )


@pytest.mark.parametrize("transport", ["UNIXROS", "TCPROS"], indirect=True)
def test_the_bytes_published_count_each_message_once_as_subscribers_come_and_go(
    make_node: Callable[..., Node], transport: str
) -> None:
    """``getBusStats``' messageDataSent: the bytes of every message published, once, whether
    sent the one-subscriber way, to a subscriber since gone, or to none (in one process
    nothing is serialized, so only the socket transports)."""
    talker = make_node("talker")
    pub = talker.advertise("/count", String, queue_size=None)
    first: list[str] = []
    sub = make_node("first").subscribe("/count", String, lambda m: first.append(m.data))
    wait_for(connected(pub, sub))
    sent = []
    for text in ("one", "two"):
        pub.publish(String(data=text))
        sent.append(String(data=text)._frame())
    wait_for(lambda: first == ["one", "two"])
    sub.unregister()
    wait_for(lambda: pub.get_num_connections() == 0)
    pub.publish(String(data="to nobody"))
    sent.append(String(data="to nobody")._frame())
    second: list[str] = []
    sub = make_node("second").subscribe("/count", String, lambda m: second.append(m.data))
    wait_for(connected(pub, sub))
    pub.publish(String(data="four"))
    sent.append(String(data="four")._frame())
    wait_for(lambda: second == ["four"])
    _, _, (publications, _, _) = call(talker.uri, "getBusStats", "/test")
    assert [p[:2] for p in publications if p[0] == "/count"] == [
        ["/count", sum(len(frame) for frame in sent)]
    ]
