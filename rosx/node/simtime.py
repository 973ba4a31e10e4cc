"""Simulated time for a node: ``/use_sim_time`` read once, then ``/clock`` followed.

As rospy's ``init_node`` does (``rospy.impl.simtime``): when the master's ``/use_sim_time``
parameter is true, the node's `Clock` reads 0 until the first ``rosgraph_msgs/Clock`` message on
``/clock`` and each message's time after it (subscribed with a queue of 1); otherwise it keeps
the wall clock. The node's console lines then show its ROS time after the wall clock's, as
rospy's do. rospy scripts get this from `rosx.client` (`init_node`); other rosx programs call
`follow_sim_time` when they want ROS time to be a simulator's.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rosx.msg.codec.classes import get_message_class

if TYPE_CHECKING:
    from rosx.node.node import Node

USE_SIM_TIME = "/use_sim_time"
CLOCK = "/clock"


def follow_sim_time(node: Node) -> bool:
    """Make ``node.clock`` follow ``/clock`` if ``/use_sim_time`` is set; whether it does."""
    if not node.params.get(USE_SIM_TIME, False):
        return False
    clock = node.clock
    clock.use_sim_time()
    node.log_sink.ros_time = lambda: clock.now().to_sec()

    def tick(message: Any) -> None:
        clock.set(message.clock)

    node.subscribe(CLOCK, get_message_class("rosgraph_msgs/Clock"), tick, queue_size=1)
    return True


__all__ = ["CLOCK", "USE_SIM_TIME", "follow_sim_time"]
