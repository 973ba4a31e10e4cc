"""A drain made while a connection's thread holds bytes it has read and not yet counted
(`Subscription.make_drains_exact`): it waits for them, where a plain drain misses them. An
action client relies on it so that a result never overtakes the feedback sent before it.

The test holds the thread at that very point: the connection's socket is wrapped so that its
next read takes everything published, then waits for the test."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from rosx.msg.codec.classes import get_message_class
from rosx.node import Node, local, unixros
from tests.support.frames import HeldRead
from tests.support.procs import wait_for

Twist = get_message_class("geometry_msgs/Twist")
Vector3 = get_message_class("geometry_msgs/Vector3")


@pytest.fixture(autouse=True, params=["UNIXROS", "TCPROS"])
def transport(request: pytest.FixtureRequest, monkeypatch: pytest.MonkeyPatch) -> str:
    monkeypatch.setattr(local, "ENABLED", False)
    monkeypatch.setattr(unixros, "ENABLED", request.param == "UNIXROS")
    return str(request.param)


def _check_held_read(pub: Any, sub: Any, got: list[float], before: list[float]) -> None:
    """Five messages read at once by a thread then held before it counts them: a drain made
    meanwhile is not done until their callbacks have run."""
    stream: Any = next(iter(sub.subscription.streams.values()))
    real = stream.sock
    held = HeldRead(real)
    stream.sock = held
    try:
        for number in range(5):
            pub.publish(Twist(linear=Vector3(x=float(number))))
        wait_for(lambda: pub.delivered_to() == {"/exact_sub"}, what="the messages sent")
        held.published.set()
        assert held.taken.wait(10), "the thread did not read through the wrapped socket"
        drain = sub.drain()  # every byte is out of the socket, none counted
        assert not drain.done()
        assert got == before
        held.go.set()
        wait_for(drain.done, what="the drain")
        assert got == [*before, 0.0, 1.0, 2.0, 3.0, 4.0]
    finally:
        held.release()
        stream.sock = real


def test_an_exact_drain_waits_for_the_bytes_a_read_holds(
    make_node: Callable[..., Node],
) -> None:
    a, b = make_node("exact_pub"), make_node("exact_sub")
    got: list[float] = []
    sub = b.subscribe("/exact", Twist, lambda m: got.append(m.linear.x), queue_size=None)
    sub.make_drains_exact()
    pub = a.advertise("/exact", Twist, queue_size=None)
    wait_for(lambda: pub.get_num_connections() > 0 and sub.get_num_connections() > 0)
    pub.publish(Twist(linear=Vector3(x=-1.0)))
    wait_for(lambda: got == [-1.0], what="the first message")  # the thread waits for data
    _check_held_read(pub, sub, got, [-1.0])


def test_drains_made_exact_on_a_busy_connection_are_exact_from_its_next_message(
    make_node: Callable[..., Node],
) -> None:
    """A second action client of the same action in a node shares the first one's topic,
    whose connections are read already."""
    a, b = make_node("exact_pub"), make_node("exact_sub")
    got: list[float] = []
    sub = b.subscribe("/exact", Twist, lambda m: got.append(m.linear.x), queue_size=None)
    pub = a.advertise("/exact", Twist, queue_size=None)
    wait_for(lambda: pub.get_num_connections() > 0 and sub.get_num_connections() > 0)
    pub.publish(Twist(linear=Vector3(x=-2.0)))
    wait_for(lambda: got == [-2.0], what="the first message")  # the thread waits in recv
    sub.make_drains_exact()
    pub.publish(Twist(linear=Vector3(x=-1.0)))  # read as before; the reads after it counted
    wait_for(lambda: got == [-2.0, -1.0], what="the second message")
    _check_held_read(pub, sub, got, [-2.0, -1.0])
