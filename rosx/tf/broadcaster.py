"""``tf2_ros.TransformBroadcaster`` and ``StaticTransformBroadcaster``.

A broadcaster publishes ``tf2_msgs/TFMessage`` on ``/tf`` (queue 100), a static one on the
latched ``/tf_static``. Every broadcaster of a node shares one publisher, so the upstream
tutorials' habit of making a broadcaster per message (about 62 a second) costs nothing.

Static transforms accumulate: each ``sendTransform`` publishes every static transform the node
has sent so far (the latest per child frame), as ROS 1's C++ broadcaster does; ROS 1's Python
one latches only the last list sent, so a second call hides the first from late subscribers.
"""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, Any

from rosx.tf import ros

if TYPE_CHECKING:
    from rosx.node import Node


def _as_list(transform: Any) -> list[Any]:
    return list(transform) if isinstance(transform, (list, tuple)) else [transform]


class TransformBroadcaster:
    """Sends transforms on ``/tf``; ``node=`` sends as that `rosx.node.Node`."""

    def __init__(self, node: Node | None = None) -> None:
        place = ros.endpoint(node)
        self._message = ros.message_class("tf2_msgs/TFMessage")
        self.pub_tf = ros.shared(
            place, "/tf", lambda: place.advertise("/tf", self._message, 100, False)
        )

    def sendTransform(self, transform: Any) -> None:  # noqa: N802 - tf2_ros's name
        """Send a ``geometry_msgs/TransformStamped``, or a list of them."""
        self.pub_tf.publish(self._message(_as_list(transform)))


class _StaticSet:
    """A node's static transforms, latest per child frame, and their latched publisher."""

    def __init__(self, place: ros.Endpoint, message: Any) -> None:
        self.lock = threading.Lock()
        self.by_child: dict[str, Any] = {}
        self.message = message
        self.publisher = place.advertise("/tf_static", message, 100, True)

    def send(self, transforms: list[Any]) -> None:
        with self.lock:
            for t in transforms:
                self.by_child[t.child_frame_id] = t
            self.publisher.publish(self.message(list(self.by_child.values())))


class StaticTransformBroadcaster:
    """Sends transforms on the latched ``/tf_static``; ``node=`` as that node."""

    def __init__(self, node: Node | None = None) -> None:
        place = ros.endpoint(node)
        message = ros.message_class("tf2_msgs/TFMessage")
        self._set: _StaticSet = ros.shared(place, "/tf_static", lambda: _StaticSet(place, message))
        self.pub_tf = self._set.publisher

    def sendTransform(self, transform: Any) -> None:  # noqa: N802 - tf2_ros's name
        """Send a ``geometry_msgs/TransformStamped``, or a list of them (kept for late
        subscribers with every static transform sent before)."""
        self._set.send(_as_list(transform))


__all__ = ["StaticTransformBroadcaster", "TransformBroadcaster"]
