"""The core's ``/rosout`` node: every node's log records, gathered on ``/rosout_agg``.

As ROS 1's rosout node: it subscribes to ``/rosout`` and republishes each record unchanged on
``/rosout_agg``; it does not log to ``/rosout`` itself. Its logger services come with every node.
"""

from __future__ import annotations

import asyncio
from collections.abc import Awaitable, Callable, Mapping

from rosx.msg.codec.classes import get_message_class
from rosx.msg.codec.message import Message
from rosx.node.node import Node

ROSOUT_QUEUE = 100


def start_aggregator(master_uri: str, environ: Mapping[str, str] | None = None) -> Node:
    """Start ``/rosout`` against the master at ``master_uri``; the caller shuts it down."""
    log = get_message_class("rosgraph_msgs/Log")
    node = Node("/rosout", master_uri=master_uri, environ=environ, rosout_enabled=False).start()
    aggregate = node.advertise("/rosout_agg", log, queue_size=ROSOUT_QUEUE)

    def republish(record: Message) -> None:
        aggregate.publish(record)

    node.subscribe("/rosout", log, republish, queue_size=ROSOUT_QUEUE)
    return node


def core_hook(
    environ: Mapping[str, str] | None = None,
) -> Callable[[str], Awaitable[Callable[[], Awaitable[None]]]]:
    """The ``start_rosout`` hook `rosx.master.core.run_core` awaits once the master is up."""

    async def start(master_uri: str) -> Callable[[], Awaitable[None]]:
        node = await asyncio.to_thread(start_aggregator, master_uri, environ)

        async def stop() -> None:
            await asyncio.to_thread(node.shutdown, "core shutting down")

        return stop

    return start
