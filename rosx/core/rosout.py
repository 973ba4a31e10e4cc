"""The core's ``/rosout`` node: every node's log records, gathered on ``/rosout_agg``.

As ROS 1's rosout node: it subscribes to ``/rosout`` and republishes each record unchanged on
``/rosout_agg``; it does not log to ``/rosout`` itself. Its logger services come with every node.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosx.msg.codec.classes import get_message_class
from rosx.node.node import Node

if TYPE_CHECKING:
    from collections.abc import Mapping

    from rosx.msg.codec.message import Message

ROSOUT_QUEUE = 100


def start_rosout(master_uri: str, environ: Mapping[str, str]) -> Node:
    """Start ``/rosout`` against the master at ``master_uri``; the caller shuts it down."""
    log = get_message_class("rosgraph_msgs/Log")
    node = Node("/rosout", master_uri=master_uri, environ=environ, rosout_enabled=False).start()
    try:
        aggregate = node.advertise("/rosout_agg", log, queue_size=ROSOUT_QUEUE)

        def republish(record: Message) -> None:
            aggregate.publish(record)

        node.subscribe("/rosout", log, republish, queue_size=ROSOUT_QUEUE)
    except BaseException:
        node.shutdown("start-up failed")
        raise
    return node
