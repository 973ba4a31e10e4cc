"""``rospy.topics`` for scripts that rosx runs (see the ``rospy`` package)."""

from rosx.client.topics import (
    Publisher,
    SubscribeListener,
    Subscriber,
)

__all__ = ["Publisher", "SubscribeListener", "Subscriber"]
