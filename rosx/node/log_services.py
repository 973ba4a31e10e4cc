"""What every node does for logging, as rospy nodes do: publish ``/rosout``, serve its levels.

`RosoutPublisher` turns a node's log records into ``rosgraph_msgs/Log`` messages on
``/rosout`` (latched, queue of 100, as rospy advertises it), with the node's topics and a
stamp of the node's ROS time (its `Clock`). `advertise_logger_services` serves
``~get_loggers`` (``roscpp/GetLoggers``) and ``~set_logger_level``
(``roscpp/SetLoggerLevel``) over the node's `NodeLog` levels; an unknown level name is logged
as rospy logs it, ``Bad logging level: X``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class, get_service_class
from rosx.node import rosout

if TYPE_CHECKING:
    from rosx.node.node import Node


class RosoutPublisher:
    """Publishes a node's records on ``/rosout`` (a `NodeLog` ``publish`` sink)."""

    def __init__(self, node: Node) -> None:
        self.node = node
        self.log_class = get_message_class("rosgraph_msgs/Log")
        self.publisher = node.advertise("/rosout", self.log_class, queue_size=100, latch=True)

    def __call__(self, level: int, message: str, file: str, function: str, line: int) -> None:
        """Publish one log record on ``/rosout``; dropped once the node is shutting down."""
        node = self.node
        if node.is_shutdown():
            return
        record = self.log_class(
            level=level,
            name=node.name,
            msg=message,
            file=file,
            function=function,
            line=line,
            topics=list(dict.fromkeys([*node.publications, *node.subscriptions])),
        )
        record.header.stamp = node.clock.now()
        self.publisher.publish(record)


def advertise_logger_services(node: Node) -> None:
    """Serve ``~get_loggers`` and ``~set_logger_level`` for ``node``."""
    logger_class = get_message_class("roscpp/Logger")
    levels = node.log_sink

    def get_loggers(request: Any) -> Any:
        return {"loggers": [logger_class(name, level) for name, level in levels.get_loggers()]}

    def set_logger_level(request: Any) -> Any:
        if not levels.set_logger_level(request.logger, request.level):
            node.log(rosout.ERROR, f"Bad logging level: {request.level.upper()}")
        return {}

    node.advertise_service("~get_loggers", get_service_class("roscpp/GetLoggers"), get_loggers)
    node.advertise_service(
        "~set_logger_level", get_service_class("roscpp/SetLoggerLevel"), set_logger_level
    )
