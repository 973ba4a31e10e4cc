"""Buffer, TransformListener and the broadcasters over rosx nodes (``node=``), in one process."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import Any

import pytest

from rosx.client.timing import Duration, Time
from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node
from rosx.tf import (
    Buffer,
    LookupException,
    StaticTransformBroadcaster,
    TransformBroadcaster,
    TransformListener,
)

TransformStamped = get_message_class("geometry_msgs/TransformStamped")


def _transform(parent: str, child: str, x: float, secs: int = 0, nsecs: int = 0) -> Any:
    t = TransformStamped()
    t.header.frame_id = parent
    t.header.stamp.secs = secs
    t.header.stamp.nsecs = nsecs
    t.child_frame_id = child
    t.transform.translation.x = x
    t.transform.rotation.w = 1.0
    return t


def _wait(condition: Callable[[], object], what: str, timeout: float = 10.0) -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out waiting for {what}")
        time.sleep(0.01)


def test_a_listener_reads_what_broadcasters_send(make_node: Callable[..., Node]) -> None:
    talker = make_node("talker")
    reader = make_node("reader")
    buffer = Buffer(node=reader)
    listener = TransformListener(buffer, node=reader)
    StaticTransformBroadcaster(node=talker).sendTransform(_transform("world", "base", 1.0))
    StaticTransformBroadcaster(node=talker).sendTransform(_transform("base", "laser", 0.5))
    moving = TransformBroadcaster(node=talker)
    now = time.time_ns()
    sent = _transform("world", "turtle1", 3.0, now // 10**9, now % 10**9)

    def arrived() -> bool:
        moving.sendTransform(sent)
        return bool(buffer.can_transform("laser", "turtle1", Time()))

    _wait(arrived, "the transforms")
    t = buffer.lookup_transform("laser", "turtle1", sent.header.stamp)
    assert (t.header.frame_id, t.child_frame_id) == ("laser", "turtle1")
    assert t.transform.translation.x == pytest.approx(1.5)
    assert t.header.stamp == sent.header.stamp
    frames = buffer.all_frames_as_yaml()
    assert "laser: \n  parent: 'base'\n  broadcaster: '/talker'\n  rate: 10000.000\n" in frames
    with pytest.raises(LookupException):
        buffer.lookup_transform("laser", "nowhere", sent.header.stamp)
    listener.unregister()


def test_every_buffer_serves_its_frames(make_node: Callable[..., Node]) -> None:
    node = make_node("viewer")
    buffer = Buffer(node=node)
    buffer.set_transform(_transform("a", "b", 2.0, 5), "me")
    Buffer(node=node)  # a second buffer leaves the first one's service in place
    frame_graph = get_service_class("tf2_msgs/FrameGraph")
    client = node.service_client("/viewer/tf2_frames", frame_graph)
    answer = client.call(frame_graph._request_class())
    assert answer.frame_yaml == (
        "b: \n  parent: 'a'\n  broadcaster: 'me'\n  rate: 10000.000\n"
        "  most_recent_transform: 5.000\n  oldest_transform: 5.000\n  buffer_length: 0.000\n"
    )


def test_a_wait_ends_when_the_transform_arrives(make_node: Callable[..., Node]) -> None:
    node = make_node("waiter")
    buffer = Buffer(node=node, debug=False)
    later = threading.Timer(0.2, lambda: buffer.set_transform(_transform("a", "b", 1.0, 7), "x"))
    later.start()
    t = buffer.lookup_transform("a", "b", Time(7), Duration(30))
    assert t.transform.translation.x == 1.0
    later.join()
