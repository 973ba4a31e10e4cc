"""A fixed topic source for rqt_topic's pane: Lab 1's topics, messages on demand."""

from __future__ import annotations

from rosx.msg.codec.classes import get_message_class
from rosx_commands.rqt_topic.monitor import (
    Reading,
)

Pose = get_message_class("turtlesim/Pose")


LAB1_TOPICS = [
    ("/rosout", "rosgraph_msgs/Log"),
    ("/rosout_agg", "rosgraph_msgs/Log"),
    ("/turtle1/cmd_vel", "geometry_msgs/Twist"),
    ("/turtle1/color_sensor", "turtlesim/Color"),
    ("/turtle1/pose", "turtlesim/Pose"),
]


class StaticSource:
    """Lab 1's topics; a monitored topic reads as a turtle pose at 62.5 Hz."""

    def __init__(self) -> None:
        self.list = list(LAB1_TOPICS)
        self.watching: list[str] = []
        self.count = 10
        self.closed = False

    def topics(self) -> list[tuple[str, str]]:
        return list(self.list)

    def monitor(self, topic: str, type_name: str) -> None:
        self.watching.append(topic)

    def unmonitor(self, topic: str) -> None:
        self.watching.remove(topic)

    def reading(self, topic: str) -> Reading:
        pose = Pose(x=5.544445, y=5.544445, theta=0.0, linear_velocity=2.0)
        return Reading(1250.0, 62.5, self.count, pose)

    def close(self) -> None:
        self.closed = True
