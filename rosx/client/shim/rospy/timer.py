"""``rospy.timer`` for scripts that rosx runs (see the ``rospy`` package)."""

from rosx.client.timing import (
    Rate,
    Timer,
    TimerEvent,
    sleep,
)

__all__ = ["Rate", "Timer", "TimerEvent", "sleep"]
