"""turtle_actionlib's C++ programs, in Python on rosx's rospy and actionlib, with roscpp's lines.

``shape_server`` (node ``turtle_shape``, action named after the node, turtle_actionlib/Shape)
drives turtlesim's ``turtle1`` along a regular polygon: for a goal of ``edges`` and ``radius``
the polygon's apothem is ``radius·cos(π/edges)``, its side ``2·apothem·tan(π/edges)``, its
interior angle ``(edges - 2)·π/edges`` (the result reports both). From each ``/turtle1/pose``
it commands ``/turtle1/cmd_vel``: forward at 6 times the distance left on the edge, then turning at
6 times the angle left to the next edge's heading, to within 1e-5, edge after edge; then the goal
succeeds. A cancel preempts it.

``shape_client`` (node ``test_shape``) asks ``turtle_shape`` for a pentagon of radius 1.3 and
waits 40 s for it.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class
from rosx_turtle.actionlib_tutorials import start, state_name

if TYPE_CHECKING:
    from collections.abc import Sequence
    from types import ModuleType

#: Gains of the distance and angle errors, and how close counts as there.
LINEAR_GAIN = 6.0
ANGULAR_GAIN = 6.0
TOLERANCE = 0.00001


def normalize_angle_positive(angle: float) -> float:
    """``angle`` in [0, 2π), as ``angles::normalize_angle_positive``."""
    return math.fmod(math.fmod(angle, 2.0 * math.pi) + 2.0 * math.pi, 2.0 * math.pi)


def polygon(edges: int, radius: float) -> tuple[float, float, float]:
    """``(interior angle, apothem, side length)`` of the regular polygon."""
    interior = (edges - 2) * math.pi / edges
    apothem = radius * math.cos(math.pi / edges)
    return interior, apothem, apothem * 2 * math.tan(math.pi / edges)


def command(
    side: float, interior: float, start: tuple[float, float, float], pose: Any
) -> tuple[float, float, bool]:
    """``(linear, angular, edge done)`` for ``pose`` on the edge begun at ``start`` (x, y, θ)."""
    travelled = math.hypot(start[0] - pose.x, start[1] - pose.y)
    distance_error = side - abs(travelled)
    angle_error = normalize_angle_positive(math.pi - interior - (pose.theta - start[2]))
    if distance_error > TOLERANCE:
        return LINEAR_GAIN * distance_error, 0.0, False
    if abs(angle_error) > TOLERANCE:
        return 0.0, ANGULAR_GAIN * angle_error, False
    return 0.0, 0.0, True


class ShapeServer:
    """The shape server: goal and preempt callbacks, and a control step per pose."""

    def __init__(self, rospy: ModuleType, name: str) -> None:
        from rosx.actionlib import SimpleActionServer  # noqa: PLC0415 - with the node

        self.rospy = rospy
        self.name = name
        self.action = get_message_class("turtle_actionlib/ShapeAction")
        self.result_type = get_message_class("turtle_actionlib/ShapeResult")
        self.twist = get_message_class("geometry_msgs/Twist")
        self.edges = self.progress = 0
        self.interior = self.side = 0.0
        self.result: Any = self.result_type()
        self.start: tuple[float, float, float] | None = None
        self.server = SimpleActionServer(name, self.action, auto_start=False)
        self.server.register_goal_callback(self.on_goal)
        self.server.register_preempt_callback(self.on_preempt)
        pose = get_message_class("turtlesim/Pose")
        rospy.Subscriber("/turtle1/pose", pose, self.on_pose, queue_size=1)
        self.publisher = rospy.Publisher("/turtle1/cmd_vel", self.twist, queue_size=1)
        self.server.start()

    def on_goal(self) -> None:
        """Goal callback: accept the new goal and plan its polygon (interior angle, side length);
        the turtle starts on the next pose."""
        goal = self.server.accept_new_goal()
        self.edges = goal.edges
        self.interior, apothem, self.side = polygon(goal.edges, goal.radius)
        self.result = self.result_type(interior_angle=self.interior, apothem=apothem)
        self.progress = 0
        self.start = None

    def on_preempt(self) -> None:
        """Preempt callback: log ``Preempted`` and stop the goal, as turtle_actionlib's
        shape_server."""
        self.rospy.loginfo("%s: Preempted", self.name)
        self.server.set_preempted()

    def on_pose(self, pose: Any) -> None:
        """Pose callback, one control step: publish the twist toward the next corner, and succeed
        once every edge is drawn."""
        if not self.server.is_active():
            return
        if self.progress >= self.edges:
            self.rospy.loginfo("%s: Succeeded", self.name)
            self.server.set_succeeded(self.result)
            return
        if self.start is None:
            self.start = (pose.x, pose.y, pose.theta)
        linear, angular, done = command(self.side, self.interior, self.start, pose)
        if done:
            self.start = None
            self.progress += 1
        cmd = self.twist()
        cmd.linear.x, cmd.angular.z = linear, angular
        self.publisher.publish(cmd)


def run_shape_server(argv: Sequence[str]) -> int:
    """The shape server."""
    rospy = start("shape_server", "turtle_shape", argv)
    ShapeServer(rospy, rospy.get_name())
    rospy.spin()
    return 0


def run_shape_client(argv: Sequence[str]) -> int:
    """The shape client: a pentagon of radius 1.3, 40 s."""
    rospy = start("shape_client", "test_shape", argv)
    from rosx.actionlib import SimpleActionClient  # noqa: PLC0415 - with the node

    client = SimpleActionClient("turtle_shape", get_message_class("turtle_actionlib/ShapeAction"))
    rospy.loginfo("Waiting for action server to start.")
    client.wait_for_server()
    rospy.loginfo("Action server started, sending goal.")
    goal = get_message_class("turtle_actionlib/ShapeGoal")(edges=5, radius=1.3)
    client.send_goal(goal)
    if client.wait_for_result(rospy.Duration(40.0)):
        rospy.loginfo("Action finished: %s", state_name(client.get_state()))
    else:
        rospy.loginfo("Action did not finish before the time out.")
    return 0


__all__ = [
    "ShapeServer",
    "command",
    "normalize_angle_positive",
    "polygon",
    "run_shape_client",
    "run_shape_server",
]
