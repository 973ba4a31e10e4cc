"""rviz's tools that publish: "2D Nav Goal", "2D Pose Estimate" and "Publish Point".

Each places a pose (or a point) in the fixed frame and publishes it as rviz does: the goal as
``geometry_msgs/PoseStamped`` on ``/move_base_simple/goal``, the estimate as
``geometry_msgs/PoseWithCovarianceStamped`` on ``/initialpose`` (rviz's standard deviations:
0.5 m in x and y, π/12 in θ), the point as ``geometry_msgs/PointStamped`` on
``/clicked_point``, each stamped now, with rviz's log line. A config's ``Tools`` may name other
topics. Keys are rviz's shortcuts (``g``, ``p``, ``c``); the footer names the tools "Goal",
"Pose" and "Point".
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

from rosx_commands.rviz.geometry import quaternion_of_yaw

if TYPE_CHECKING:
    from collections.abc import Sequence

    from rosx_commands.rviz.config import ToolSpec

STD_X = STD_Y = 0.5
STD_THETA = math.pi / 12.0


@dataclass(frozen=True)
class Tool:
    """One publishing tool: its rviz class, name, key, footer word, topic and message type."""

    class_id: str
    title: str
    key: str
    word: str
    topic: str
    message_type: str

    @property
    def heading(self) -> bool:
        """Whether the tool places a heading too (the pose tools)."""
        return self.message_type != "geometry_msgs/PointStamped"


GOAL = Tool(
    "rviz/SetGoal",
    "2D Nav Goal",
    "g",
    "Goal",
    "/move_base_simple/goal",
    "geometry_msgs/PoseStamped",
)
POSE = Tool(
    "rviz/SetInitialPose",
    "2D Pose Estimate",
    "p",
    "Pose",
    "/initialpose",
    "geometry_msgs/PoseWithCovarianceStamped",
)
POINT = Tool(
    "rviz/PublishPoint",
    "Publish Point",
    "c",
    "Point",
    "/clicked_point",
    "geometry_msgs/PointStamped",
)
TOOLS = (GOAL, POSE, POINT)


def configured(specs: Sequence[ToolSpec]) -> tuple[Tool, ...]:
    """The three tools with the topics a config's ``Tools`` give them."""
    topics = {spec.class_id: spec.topic for spec in specs if spec.topic}
    return tuple(replace(tool, topic=topics.get(tool.class_id, tool.topic)) for tool in TOOLS)


def fill(tool: Tool, msg: Any, fixed: str, stamp: Any, x: float, y: float, yaw: float) -> Any:
    """``msg`` (an empty message of the tool's type) set as rviz sets it."""
    msg.header.frame_id = fixed
    msg.header.stamp = stamp
    if tool.message_type == "geometry_msgs/PointStamped":
        msg.point.x, msg.point.y, msg.point.z = x, y, 0.0
        return msg
    pose = msg.pose.pose if tool.message_type.endswith("WithCovarianceStamped") else msg.pose
    pose.position.x, pose.position.y, pose.position.z = x, y, 0.0
    o = pose.orientation
    o.x, o.y, o.z, o.w = quaternion_of_yaw(yaw)
    if pose is not msg.pose:
        covariance = [0.0] * 36
        covariance[0], covariance[7] = STD_X**2, STD_Y**2
        covariance[35] = STD_THETA**2
        msg.pose.covariance = covariance
    return msg


def log_line(tool: Tool, fixed: str, x: float, y: float, yaw: float) -> str:
    """What rviz logs when the tool publishes."""
    if tool.message_type == "geometry_msgs/PointStamped":
        return f"Publishing point: [{x:.3f}, {y:.3f}, 0.000] [frame={fixed}]"
    qx, qy, qz, qw = quaternion_of_yaw(yaw)
    if tool.message_type.endswith("WithCovarianceStamped"):
        return f"Setting pose: {x:.3f} {y:.3f} {yaw:.3f} [frame={fixed}]"
    return (
        f"Setting goal: Frame:{fixed}, Position({x:.3f}, {y:.3f}, 0.000), "
        f"Orientation({qx:.3f}, {qy:.3f}, {qz:.3f}, {qw:.3f}) = Angle: {yaw:.3f}"
    )


__all__ = ["GOAL", "POINT", "POSE", "TOOLS", "Tool", "configured", "fill", "log_line"]
