"""turtle_tf2's demo as nodes of this process: what ``rosx sim --tf-demo`` adds to the pond.

The same graph ``roslaunch turtle_tf2 turtle_tf2_demo.launch`` starts beside turtlesim and
the teleop: ``/turtle1_tf2_broadcaster`` and ``/turtle2_tf2_broadcaster`` send each turtle's
pose as the transform ``world`` -> ``turtleN`` on ``/tf`` (`rosx.tf.TransformBroadcaster`), and
``/turtle_pointer`` spawns turtle2 at (4, 2) and, ten times a second, looks up turtle1 in
turtle2's frame (`rosx.tf.Buffer`, fed by a `rosx.tf.TransformListener`) and drives turtle2
towards it: turning by 4 x the bearing, at 0.5 x the distance. Other terminals see the same
nodes, topics and frames as with the launch file (``rosx tf_echo turtle2 turtle1``,
``rosx rqt_tf_tree``).
"""

from __future__ import annotations

import math
import threading
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import Node

if TYPE_CHECKING:
    from collections.abc import Mapping

#: The listener's rate (Hz), as the demo's ``rospy.Rate(10.0)``.
RATE = 10.0
#: Where the listener spawns turtle2, as the demo does.
SPAWN_AT = (4.0, 2.0, 0.0)


def _pose_to_tf(broadcaster: Any, turtle: str, transform_class: type[Any]) -> Any:
    def send(pose: Any) -> None:
        t = transform_class()
        now = _now()
        t.header.stamp.secs, t.header.stamp.nsecs = now // 1_000_000_000, now % 1_000_000_000
        t.header.frame_id = "world"
        t.child_frame_id = turtle
        t.transform.translation.x = pose.x
        t.transform.translation.y = pose.y
        t.transform.rotation.z = math.sin(pose.theta / 2.0)
        t.transform.rotation.w = math.cos(pose.theta / 2.0)
        broadcaster.sendTransform(t)

    return send


def _now() -> int:
    import time  # noqa: PLC0415 - time is not needed at start-up

    return time.time_ns()


class TfDemo:
    """The demo's three nodes on the master at ``ROS_MASTER_URI`` of ``environ``; `start`,
    `stop`."""

    def __init__(self, environ: Mapping[str, str]) -> None:
        self.environ = environ
        self.nodes: list[Node] = []
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def start(self) -> TfDemo:
        """Start the broadcasters and the listener (whose loop runs on a thread of its own)."""
        from rosx.tf import Buffer, TransformBroadcaster, TransformListener  # noqa: PLC0415 - tf code loads only when used

        pose = get_message_class("turtlesim/Pose")
        transform = get_message_class("geometry_msgs/TransformStamped")
        for turtle in ("turtle1", "turtle2"):
            node = self._node(f"{turtle}_tf2_broadcaster")
            node.params.set("~turtle", turtle)
            broadcaster = TransformBroadcaster(node=node)
            node.subscribe(f"/{turtle}/pose", pose, _pose_to_tf(broadcaster, turtle, transform))
        pointer = self._node("turtle_pointer")
        buffer = Buffer(node=pointer)
        TransformListener(buffer, node=pointer)
        self._thread = threading.Thread(
            target=self._follow, args=(pointer, buffer), name="rosx-tf-demo", daemon=True
        )
        self._thread.start()
        return self

    def _node(self, name: str) -> Node:
        node = Node(name, environ=self.environ, rosout_enabled=True).start()
        self.nodes.append(node)
        return node

    def _follow(self, node: Node, buffer: Any) -> None:
        """The listener: spawn turtle2, then steer it towards turtle1 until stopped."""
        from rosx.tf import TransformException  # noqa: PLC0415 - tf code loads only when used

        spawn = get_service_class("turtlesim/Spawn")
        twist = get_message_class("geometry_msgs/Twist")
        try:
            client = node.service_client("spawn", spawn)
            x, y, theta = SPAWN_AT
            client.call(spawn._request_class(x=x, y=y, theta=theta, name="turtle2"))
        except Exception:  # turtle2 is there already (a second demo): follow it anyway
            pass
        cmd_vel = node.advertise("turtle2/cmd_vel", twist, queue_size=1)
        period = 1.0 / RATE
        while not self._stop.wait(period) and not node.is_shutdown():
            try:
                _, (tx, ty, *_) = buffer.lookup("turtle2", "turtle1", 0)
            except TransformException:
                continue
            msg = twist()
            msg.angular.z = 4 * math.atan2(ty, tx)
            msg.linear.x = 0.5 * math.sqrt(tx**2 + ty**2)
            cmd_vel.publish(msg)

    def stop(self) -> None:
        """Stop the loop and shut the nodes down."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(2.0)
        for node in reversed(self.nodes):
            node.shutdown("rosx sim is done")
        self.nodes.clear()


__all__ = ["RATE", "SPAWN_AT", "TfDemo"]
